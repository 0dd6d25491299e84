#include "sssFileClaims.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>
#include <sstream>
#include <vector>

#include "sssPclLoading.h"

namespace sss {
namespace {

// Headers larger than this are refused before their lines are read into memory.
constexpr std::size_t kMaxHeaderLines = 4096;
constexpr std::size_t kMaxHeaderLineBytes = 1 << 16;

// Bytes a PLY face holds in memory at least: a pcl::Vertices (one std::vector) and three
// indices on the heap; other elements, one small record each.
constexpr long double kFaceBytes = 56;
constexpr long double kOtherElementBytes = 32;
// An OBJ vertex: its position, the normal it is given and the clouds made of them; a vn line's
// normal; a face corner past the third. A line of an ASCII point list: its values as parsed,
// the cloud and PCL's blob of them.
constexpr long double kObjVertexBytes = 128;
constexpr long double kObjNormalBytes = 12;
constexpr long double kCornerBytes = 4;
constexpr long double kPointLineBytes = 132;
// Text formats are counted through a buffer of this size.
constexpr std::size_t kChunkBytes = 1 << 20;

[[noreturn]] void refuse(const std::string& shown, const std::string& what) {
  throw InputError(shown + ": " + what);
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// A whole number of at most 19 digits (no sign), or refuse naming the key.
std::uint64_t whole(const std::string& shown, const std::string& key, const std::string& text) {
  if (text.empty() || text.size() > 19 ||
      !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
    refuse(shown, "its header's " + key + " '" + text + "' is not a whole number");
  return std::stoull(text);
}

bool is_number(const std::string& text) {
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

std::uint64_t file_size(const std::string& shown, const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) refuse(shown, "cannot read its size (" + error.message() + ")");
  return size;
}

// Reads one line without its end ('\n', and a '\r' before it); false when it runs past
// kMaxHeaderLineBytes, which `line` then holds the start of.
bool read_bounded_line(std::istream& in, std::string& line) {
  line.clear();
  char c;
  while (in.get(c) && c != '\n') {
    if (line.size() >= kMaxHeaderLineBytes) return false;
    line.push_back(c);
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

// Reads header lines up to and including `last_key`, with bounded size; returns them and
// sets `data_offset` to the byte after the last one.
std::vector<std::string> header_lines(const std::string& shown, std::ifstream& in,
                                      const std::string& last_key, const char* format,
                                      std::uint64_t& data_offset) {
  const std::string unreadable = std::string("not a readable ") + format + " file (";
  std::vector<std::string> lines;
  std::string line;
  while (lines.size() < kMaxHeaderLines) {
    if (!read_bounded_line(in, line))
      refuse(shown, unreadable + "a header line is over " + byteSize(kMaxHeaderLineBytes) + ")");
    if (!in && line.empty()) break;
    lines.push_back(line);
    const std::vector<std::string> w = words(line);
    if (!w.empty() && w[0] == last_key) {
      // At the end of the file there is no data after the header.
      data_offset = in ? static_cast<std::uint64_t>(in.tellg())
                       : std::numeric_limits<std::uint64_t>::max();
      return lines;
    }
    if (!in) break;
  }
  if (lines.size() < kMaxHeaderLines)
    refuse(shown, unreadable + "its header has no " + last_key + " line)");
  refuse(shown, unreadable + "no " + last_key + " line within " +
                  std::to_string(kMaxHeaderLines) + " header lines)");
}

// Two sizes that a reader must tell apart: in bytes where byteSize rounds them alike.
std::pair<std::string, std::string> sizes_apart(long double a, long double b) {
  std::string sa = byteSize(static_cast<double>(a)), sb = byteSize(static_cast<double>(b));
  if (sa == sb && sa.find("bytes") == std::string::npos) {
    sa = std::to_string(static_cast<unsigned long long>(a)) + " bytes";
    sb = std::to_string(static_cast<unsigned long long>(b)) + " bytes";
  }
  return {sa, sb};
}

bool starts_with(const std::string& text, const char* prefix) {
  return text.rfind(prefix, 0) == 0;
}

// The first header key PCL's reader would still take after the DATA line (it reads on while
// lines start with one, skipping blank, comment and VERSION lines), or an empty string.
std::string pcd_keys_after_data(std::ifstream& in) {
  const std::streampos start = in.tellg();
  std::string found;
  for (int lines = 0; lines < 64 && in && found.empty(); ++lines) {
    std::string line;
    read_bounded_line(in, line);  // only its first word matters
    const std::vector<std::string> w = words(line);
    if (w.empty() || starts_with(w[0], "#") || starts_with(w[0], "VERSION")) continue;
    for (const char* key : {"FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT",
                            "VIEWPOINT", "POINTS", "DATA"})
      if (starts_with(w[0], key)) found = key;
    break;
  }
  in.clear();
  in.seekg(start);
  return found;
}

void check_memory(const std::string& shown, const std::string& claim, long double bytes,
                  std::size_t cap, const char* source = "its header claims ") {
  if (bytes > static_cast<long double>(cap))
    refuse(shown, source + claim + ", which would need " + byteSize(bytes) +
                    " in memory, over the memory cap of " + byteSize(cap) +
                    " (LoadOptions::memory_cap, --memory-cap)");
}

void check_data(const std::string& shown, const std::string& claim, long double needed,
                std::uint64_t available) {
  if (needed > static_cast<long double>(available)) {
    const auto [need, have] = sizes_apart(needed, available);
    refuse(shown, "its header claims " + claim + ", at least " + need +
                    " of data, but the file holds " + have + " after its header");
  }
}

// An integer as PCL's PLY reader takes it: atoi, then stored in an unsigned 32-bit size.
std::uint32_t as_pcl_reads_int(const std::string& text) {
  return static_cast<std::uint32_t>(static_cast<int>(std::strtol(text.c_str(), nullptr, 10)));
}

std::string count_of(std::uint64_t n, const std::string& what) {
  return std::to_string(n) + " " + what;
}

}  // namespace

std::size_t defaultMemoryCap() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return std::size_t{4} << 30;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page) / 2;
}

std::string byteSize(double bytes) {
  const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return std::to_string(static_cast<long long>(bytes)) + " bytes";
  int unit = 0;
  for (bytes /= 1024; bytes >= 1024 && unit < 5; bytes /= 1024) ++unit;
  char text[64];
  std::snprintf(text, sizeof text, bytes < 10 ? "%.1f %s" : "%.0f %s", bytes, units[unit]);
  return text;
}

void checkPcdClaims(const std::string& shown, const std::string& path, std::size_t cap,
                    std::size_t point_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(shown, "cannot be opened");
  std::uint64_t data_offset = 0;
  const std::vector<std::string> lines = header_lines(shown, in, "DATA", "PCD", data_offset);

  std::vector<std::string> fields, sizes, types, counts;
  std::uint64_t width = 0, height = 0, points = 0;
  const auto after_data = pcd_keys_after_data(in);
  std::string data;
  std::vector<std::string> seen;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    std::vector<std::string> w = words(lines[l]);
    if (w.empty() || w[0][0] == '#') continue;
    std::string key = w[0];
    if (key == "COLUMNS") key = "FIELDS";  // PCD before 0.7
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      refuse(shown, "not a readable PCD file (its header has two " + key + " lines)");
    seen.push_back(key);
    const std::vector<std::string> values(w.begin() + 1, w.end());
    if (key == "VERSION") {
    } else if (key == "FIELDS") {
      fields = values;
    } else if (key == "SIZE") {
      sizes = values;
    } else if (key == "TYPE") {
      types = values;
    } else if (key == "COUNT") {
      counts = values;
    } else if (key == "WIDTH" && values.size() == 1) {
      width = whole(shown, key, values[0]);
    } else if (key == "HEIGHT" && values.size() == 1) {
      height = whole(shown, key, values[0]);
    } else if (key == "POINTS" && values.size() == 1) {
      points = whole(shown, key, values[0]);
    } else if (key == "VIEWPOINT") {
      if (values.size() != 7 || !std::all_of(values.begin(), values.end(), is_number))
        refuse(shown, "not a readable PCD file (VIEWPOINT needs 7 numbers)");
    } else if (key == "DATA" && values.size() == 1) {
      data = lower(values[0]);
    } else {
      refuse(shown, "not a readable PCD file (header line " + std::to_string(l + 1) + ", '" +
                      lines[l].substr(0, 40) + "', is not a PCD header line)");
    }
  }
  if (!after_data.empty())  // PCL's reader goes on reading header lines after DATA
    refuse(shown, "not a readable PCD file (a " + after_data + " line after DATA)");
  const auto at = [&](const char* key) {
    return std::find(seen.begin(), seen.end(), key) - seen.begin();
  };
  const auto absent = static_cast<std::ptrdiff_t>(seen.size());
  for (const char* required : {"FIELDS", "SIZE", "TYPE", "POINTS", "DATA"})
    if (at(required) == absent)
      refuse(shown, std::string("not a readable PCD file (its header has no ") + required +
                      " line)");
  // PCL sizes its buffer at POINTS from the fields known then.
  if (at("SIZE") < at("FIELDS") || at("TYPE") < at("SIZE") ||
      (at("COUNT") != absent && at("COUNT") < at("TYPE")) || at("POINTS") < at("TYPE") ||
      (at("COUNT") != absent && at("POINTS") < at("COUNT")))
    refuse(shown, "not a readable PCD file (its header needs FIELDS, SIZE, TYPE and COUNT in "
                  "that order, before POINTS)");
  if (at("WIDTH") == absent && at("HEIGHT") == absent) {  // PCD before 0.7: PCL's defaults
    width = points;
    height = 1;
  } else if (at("HEIGHT") == absent) {
    height = 1;
  }
  if (fields.empty()) refuse(shown, "not a readable PCD file (FIELDS names no field)");
  if (counts.empty()) counts.assign(fields.size(), "1");
  for (const auto* list : {&sizes, &types, &counts})
    if (list->size() != fields.size())
      refuse(shown, "not a readable PCD file (FIELDS names " + std::to_string(fields.size()) +
                      " fields, but SIZE, TYPE or COUNT has " + std::to_string(list->size()) +
                      " entries)");
  long double record = 0, values_per_point = 0;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const std::uint64_t size = whole(shown, "SIZE", sizes[f]);
    const std::uint64_t count = whole(shown, "COUNT", counts[f]);
    const std::string type = lower(types[f]);
    const bool known_size = size == 1 || size == 2 || size == 4 || size == 8;
    if (!known_size || (type != "i" && type != "u" && type != "f") ||
        (type == "f" && size != 4 && size != 8))
      refuse(shown, "not a readable PCD file (field " + fields[f] + " has SIZE " + sizes[f] +
                      " and TYPE " + types[f] + ")");
    if (count == 0 || count > (1u << 24))
      refuse(shown, "not a readable PCD file (field " + fields[f] + " has COUNT " + counts[f] +
                      ")");
    record += static_cast<long double>(size) * count;
    values_per_point += count;
  }
  if (static_cast<long double>(width) * height != points)
    refuse(shown, "not a readable PCD file (WIDTH " + std::to_string(width) + " x HEIGHT " +
                    std::to_string(height) + " is not POINTS " + std::to_string(points) + ")");
  if (data != "ascii" && data != "binary" && data != "binary_compressed")
    refuse(shown, "not a readable PCD file (DATA '" + data +
                    "' is none of ascii, binary, binary_compressed)");
  if (points == 0) return;  // the loader says the file has no points

  const std::uint64_t size = file_size(shown, path);
  const std::uint64_t available = size > data_offset ? size - data_offset : 0;
  const std::string claim = count_of(points, "points") + " of " + byteSize(record);
  const long double blob = record * points;
  if (data == "ascii") {
    check_data(shown, claim + " (" + data + ")", values_per_point * 2 * points - 1, available);
  } else if (data == "binary") {
    check_data(shown, claim + " (" + data + ")", blob, available);
  } else {
    std::uint32_t sizes_field[2] = {0, 0};
    in.clear();
    in.seekg(static_cast<std::streamoff>(data_offset));
    if (available < 8 || !in.read(reinterpret_cast<char*>(sizes_field), 8))
      refuse(shown, "its header claims " + claim + " (binary_compressed), but the file ends "
                    "before the compressed data's sizes");
    check_data(shown, claim + " (binary_compressed, " + byteSize(sizes_field[0]) + " compressed)",
               8.0L + sizes_field[0], available);
    if (static_cast<long double>(sizes_field[1]) != blob) {
      const auto [claimed, inflated] = sizes_apart(blob, sizes_field[1]);
      refuse(shown, "its header claims " + claim + " (" + claimed +
                      "), but its compressed data inflate to " + inflated);
    }
  }
  const long double decompression = data == "binary_compressed" ? blob : 0;
  check_memory(shown, claim, blob + decompression + static_cast<long double>(point_bytes) * points,
               cap);
}

void checkPlyClaims(const std::string& shown, const std::string& path, std::size_t cap,
                    std::size_t point_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(shown, "cannot be opened");
  std::uint64_t data_offset = 0;
  const std::vector<std::string> lines =
    header_lines(shown, in, "end_header", "PLY", data_offset);
  if (lines.empty() || lines[0] != "ply")
    refuse(shown, "not a readable PLY file (it does not begin with 'ply')");

  struct Element {
    std::string name;
    std::uint64_t count = 0;
    long double fixed_bytes = 0;  // scalars and list lengths
    long double values = 0;       // ascii tokens at least
    long double scalar_bytes = 0;
  };
  auto type_bytes = [](const std::string& t) -> int {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
        t == "float32")
      return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
  };
  std::vector<Element> elements;
  std::vector<std::string> vertex_bytes;  // the vertex element's one-byte unsigned properties
  std::string format;
  // The cloud's size as PCL's reader sets it: obj_info num_cols / num_rows, else the
  // vertex count when the vertex element is defined while either is still 0.
  std::uint32_t width = 0, height = 0;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const std::vector<std::string> w = words(lines[l]);
    const std::string where = " (header line " + std::to_string(l + 1) + ", '" +
                              lines[l].substr(0, 40) + "')";
    if (w.empty()) continue;  // PCL's parser skips blank lines
    if (w[0] == "obj_info") {
      if (lines[l][0] == ' ' || lines[l][0] == '\t')  // PCL's reader aborts on these
        refuse(shown, "not a readable PLY file (obj_info after white space" + where + ")");
      if (w.size() >= 3 && (w[1] == "num_cols" || w[1] == "num_rows"))
        (w[1] == "num_cols" ? width : height) = as_pcl_reads_int(w[2]);
      continue;
    }
    if (w[0] == "comment" || w[0] == "end_header") continue;
    if (w[0] == "format") {
      if (!format.empty() || w.size() != 3 || w[2] != "1.0" ||
          (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
        refuse(shown, "not a readable PLY file" + where);
      format = w[1];
    } else if (w[0] == "element" && w.size() == 3) {
      if (w[1] == "range_grid")  // PCL's reader indexes vertices from it unchecked
        refuse(shown, "not a readable PLY file (range_grid elements are not supported" + where +
                        ")");
      elements.push_back({w[1], whole(shown, "element " + w[1] + " count", w[2])});
      if (w[1] == "vertex") {
        if (elements.back().count > static_cast<std::uint64_t>(INT32_MAX))
          refuse(shown, "its header claims " + w[2] + " vertices, more than PCL can index");
        if (width == 0 || height == 0) {
          width = static_cast<std::uint32_t>(elements.back().count);
          height = 1;
        }
      }
    } else if (w[0] == "property" && !elements.empty() && w.size() == 3 && type_bytes(w[1])) {
      if (elements.back().name == "vertex" && (w[1] == "uchar" || w[1] == "uint8"))
        vertex_bytes.push_back(w[2]);
      elements.back().fixed_bytes += type_bytes(w[1]);
      elements.back().scalar_bytes += type_bytes(w[1]);
      elements.back().values += 1;
    } else if (w[0] == "property" && !elements.empty() && w.size() == 5 && w[1] == "list" &&
               type_bytes(w[2]) && w[2].find("float") == std::string::npos &&
               w[2] != "double" && type_bytes(w[3])) {
      if (elements.back().name == "vertex")  // PCL's reader aborts on some of these
        refuse(shown, "not a readable PLY file (a list property in the vertex element" + where +
                        ")");
      elements.back().fixed_bytes += type_bytes(w[2]);
      elements.back().values += 1;
    } else {
      refuse(shown, "not a readable PLY file" + where);
    }
  }
  if (format.empty()) refuse(shown, "not a readable PLY file (its header has no format line)");
  const auto vertex = std::find_if(elements.begin(), elements.end(),
                                   [](const Element& e) { return e.name == "vertex"; });
  if (vertex == elements.end())
    refuse(shown, "not a readable PLY file (its header has no vertex element)");

  // PCL's reader packs one-byte red, green and blue into rgb as they arrive and aborts on a
  // colour whose red is missing or comes later, and on alpha without them.
  for (const char* prefix : {"", "diffuse_"}) {
    const std::string red = std::string(prefix) + "red";
    const auto at = [&](const std::string& name) {
      return std::find(vertex_bytes.begin(), vertex_bytes.end(), name) - vertex_bytes.begin();
    };
    const auto none = static_cast<std::ptrdiff_t>(vertex_bytes.size());
    for (const std::string& later : {std::string(prefix) + "green", std::string(prefix) + "blue"})
      if (at(later) != none && !(at(red) < at(later)))
        refuse(shown, "not a readable PLY file (its vertices have a uchar " + later +
                        " without a uchar " + red + " before it)");
  }
  if (std::find(vertex_bytes.begin(), vertex_bytes.end(), "alpha") != vertex_bytes.end() &&
      std::find(vertex_bytes.begin(), vertex_bytes.end(), "red") == vertex_bytes.end() &&
      std::find(vertex_bytes.begin(), vertex_bytes.end(), "diffuse_red") == vertex_bytes.end())
    refuse(shown, "not a readable PLY file (its vertices have a uchar alpha without red, green "
                  "and blue)");
  // PCL sizes the vertices' buffer by that width and height, not by the vertex count.
  if (static_cast<std::uint64_t>(width) * height != vertex->count)
    refuse(shown, "not a readable PLY file (obj_info gives " + std::to_string(width) + " x " +
                    std::to_string(height) + " points for its " +
                    std::to_string(vertex->count) + " vertices)");

  long double data = 0, memory = 0;
  std::string claim;
  for (const Element& e : elements) {
    data += e.count * (format == "ascii" ? 2 * e.values : e.fixed_bytes);
    if (e.name == "vertex")
      memory += e.count * (e.scalar_bytes + static_cast<long double>(point_bytes));
    else
      memory += e.count * (e.name == "face" ? kFaceBytes : kOtherElementBytes);
    if (e.count == 0 && e.name != "vertex") continue;
    const std::string what = e.name == "vertex" ? "vertices"
                             : e.name == "face" ? "faces"
                                                : e.name + (e.count == 1 ? " element" : " elements");
    claim += (claim.empty() ? "" : ", ") + count_of(e.count, what);
  }
  if (data > 0 && format == "ascii") data -= 1;  // the last value needs no separator
  const std::uint64_t size = file_size(shown, path);
  check_data(shown, claim + " (" + format + ")", data, size > data_offset ? size - data_offset : 0);
  check_memory(shown, claim, memory, cap);
}

ObjCounts checkObjClaims(const std::string& shown, const std::string& path, std::size_t cap,
                         std::size_t point_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(shown, "cannot be opened");
  ObjCounts counts;
  char key[3];
  int key_length = 0;  // 3: longer than any key counted here
  bool key_done = false, in_word = false;
  std::uint64_t words = 0;  // after the key
  const auto end_line = [&] {
    const std::string k(key, static_cast<std::size_t>(std::min(key_length, 2)));
    if (key_length < 3 && k == "v") ++counts.vertices;
    if (key_length < 3 && k == "vn") ++counts.normals;
    if (key_length < 3 && k == "f") ++counts.faces, counts.corners += words;
    key_length = 0, key_done = false, in_word = false, words = 0;
  };
  std::vector<char> buffer(kChunkBytes);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const std::streamsize n = in.gcount();
    for (std::streamsize i = 0; i < n; ++i) {
      const char c = buffer[static_cast<std::size_t>(i)];
      const bool space = c == ' ' || c == '\t' || c == '\r';
      if (c == '\n') {
        end_line();
      } else if (!key_done) {
        if (space && key_length > 0) key_done = true;
        if (!space && key_length < 3) key[key_length++] = c;
      } else if (space) {
        in_word = false;
      } else if (!in_word) {
        in_word = true;
        ++words;
      }
    }
  }
  end_line();
  if (counts.vertices > static_cast<std::uint64_t>(INT32_MAX))
    refuse(shown, "its lines hold " + count_of(counts.vertices, "vertices") +
                    ", more than PCL can index");
  const long double extra_corners =
    counts.corners > 3 * counts.faces ? counts.corners - 3 * counts.faces : 0;
  check_memory(shown,
               count_of(counts.vertices, "vertices") + ", " + count_of(counts.normals, "normals") +
                 ", " + count_of(counts.faces, "faces"),
               counts.vertices * (kObjVertexBytes + static_cast<long double>(point_bytes)) +
                 counts.normals * kObjNormalBytes + counts.faces * kFaceBytes +
                 extra_corners * kCornerBytes,
               cap, "its lines hold ");
  return counts;
}

std::uint64_t checkPointListClaims(const std::string& shown, const std::string& path,
                                   std::size_t cap, std::size_t point_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(shown, "cannot be opened");
  std::uint64_t lines = 0;
  char last = '\n';
  std::vector<char> buffer(kChunkBytes);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    lines += static_cast<std::uint64_t>(std::count(buffer.data(), buffer.data() + n, '\n'));
    if (n > 0) last = buffer[n - 1];
  }
  lines += last != '\n';
  check_memory(shown, count_of(lines, "lines") + " (a point each at most)",
               lines * (kPointLineBytes + static_cast<long double>(point_bytes)), cap, "its ");
  return lines;
}

}  // namespace sss
