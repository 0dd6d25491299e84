#include "sssAsciiPoints.h"

#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "sssFileClaims.h"
#include "sssPclLoading.h"

namespace sss {
namespace {

constexpr std::size_t kLineBytes = 1 << 20;
constexpr std::string_view kSeparators = " \t,;";

// What a column is read as; kIgnored for others.
enum Role { kIgnored = -1, kX, kY, kZ, kNx, kNy, kNz, kR, kG, kB };
constexpr const char* kRoleNames[] = {"x", "y", "z", "nx", "ny", "nz", "r", "g", "b"};

Role role_named(std::string_view word) {
  std::string name(word);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  static const std::pair<const char*, Role> names[] = {
    {"x", kX}, {"y", kY}, {"z", kZ}, {"nx", kNx}, {"ny", kNy}, {"nz", kNz},
    {"normal_x", kNx}, {"normal_y", kNy}, {"normal_z", kNz}, {"r", kR}, {"g", kG}, {"b", kB},
    {"red", kR}, {"green", kG}, {"blue", kB}};
  for (const auto& [n, role] : names)
    if (name == n) return role;
  return kIgnored;
}

bool names_all(const std::vector<Role>& roles, Role first) {
  for (int r = first; r < first + 3; ++r)
    if (std::find(roles.begin(), roles.end(), static_cast<Role>(r)) == roles.end()) return false;
  return true;
}

// A header's roles: a group (normals, colours) counts only when all three are named.
std::vector<Role> header_roles(const std::vector<std::string_view>& words) {
  std::vector<Role> roles;
  for (std::string_view w : words) roles.push_back(role_named(w));
  for (Role group : {kNx, kR})
    if (!names_all(roles, group))
      for (Role& r : roles)
        if (r >= group && r < group + 3) r = kIgnored;
  return roles;
}

// The roles of 3, 4, 6, 7 or 9 unnamed columns, before the values decide between normals and
// colours (6 and 9 columns); empty for other counts.
std::vector<Role> counted_roles(std::size_t columns) {
  switch (columns) {
    case 3: return {kX, kY, kZ};
    case 4: return {kX, kY, kZ, kIgnored};
    case 6: return {kX, kY, kZ, kNx, kNy, kNz};
    case 7: return {kX, kY, kZ, kIgnored, kR, kG, kB};
    case 9: return {kX, kY, kZ, kR, kG, kB, kNx, kNy, kNz};
    default: return {};
  }
}

bool whole_number(std::string_view word) {
  return !word.empty() &&
         std::all_of(word.begin(), word.end(), [](unsigned char c) { return std::isdigit(c); });
}

}  // namespace

TextLines::TextLines(const std::string& shown, const std::string& path)
    : shown_(shown), in_(path, std::ios::binary), buffer_(kLineBytes) {
  if (!in_) throw InputError(shown + ": cannot be opened");
}

bool TextLines::next(std::string_view& line) {
  for (;;) {
    const char* start = buffer_.data() + begin_;
    const auto* end = static_cast<const char*>(std::memchr(start, '\n', end_ - begin_));
    if (end || (read_all_ && begin_ < end_)) {
      const std::size_t length = end ? static_cast<std::size_t>(end - start) : end_ - begin_;
      line = std::string_view(start, length);
      begin_ += end ? length + 1 : length;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      ++number_;
      return true;
    }
    if (read_all_) return false;
    std::memmove(buffer_.data(), start, end_ - begin_);  // the start of the next line
    end_ -= begin_;
    begin_ = 0;
    if (end_ == buffer_.size())
      throw InputError(shown_ + ": line " + std::to_string(number_ + 1) + " is longer than " +
                       byteSize(static_cast<double>(buffer_.size())));
    in_.read(buffer_.data() + end_, static_cast<std::streamsize>(buffer_.size() - end_));
    end_ += static_cast<std::size_t>(in_.gcount());
    read_all_ = !in_;
  }
}

void splitWords(std::string_view line, std::string_view separators,
                std::vector<std::string_view>& words) {
  words.clear();
  std::size_t at = line.find_first_not_of(separators);
  while (at != std::string_view::npos) {
    const std::size_t end = std::min(line.find_first_of(separators, at), line.size());
    words.push_back(line.substr(at, end - at));
    at = line.find_first_not_of(separators, end);
  }
}

bool parseNumber(std::string_view word, double& value) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
  const char* end = word.data() + word.size();
  const auto [stop, error] = std::from_chars(word.data(), end, value);
  return error == std::errc() && stop == end;
}

AsciiPoints readAsciiPoints(const std::string& path, std::size_t cap, std::size_t point_bytes) {
  const std::uint64_t lines = checkPointListClaims(path, path, cap, point_bytes);
  const auto refuse = [&](std::size_t line, const std::string& what) {
    throw InputError(path + ": line " + std::to_string(line) + ": " + what);
  };
  std::vector<Role> roles;  // of the columns, from the header or the first point's line
  bool by_header = false, header_commented = false;
  std::size_t first_point = 0;  // its line
  std::vector<Role> kept;       // roles of the values kept per point, in column order
  std::vector<float> values;    // kept.size() per point
  std::vector<std::string_view> words;
  TextLines text(path, path);
  for (std::string_view line; text.next(line);) {
    const std::size_t at = line.find_first_not_of(" \t");
    if (at == std::string_view::npos) continue;
    line.remove_prefix(at);
    const bool comment = line[0] == '#' || line.rfind("//", 0) == 0;
    splitWords(line.substr(comment ? (line[0] == '#' ? 1 : 2) : 0), kSeparators, words);
    if (words.empty()) continue;
    double number = 0;
    const bool numbers = parseNumber(words[0], number);
    if (first_point == 0 && !by_header && !numbers) {
      const std::vector<Role> named = header_roles(words);
      if (names_all(named, kX)) {
        roles = named;
        by_header = true;
        header_commented = comment;
        continue;
      }
    }
    if (comment) continue;
    if (!numbers)
      refuse(text.number(), "'" + std::string(line.substr(0, 40)) + "' is not a point" +
                              (first_point ? "" : ", a comment or a header naming x, y and z"));
    if (first_point == 0 && words.size() == 1 && whole_number(words[0]))
      continue;  // a point count, as .pts files begin
    if (first_point == 0) {
      first_point = text.number();
      if (header_commented && words.size() != roles.size())
        by_header = false;  // a comment naming x, y and z, not the columns
      if (!by_header) roles = counted_roles(words.size());
      if (roles.empty())
        refuse(first_point, std::to_string(words.size()) + " columns; without a header naming "
                            "them, use 3 (x y z), 4, 6, 7 or 9");
      for (Role r : roles)
        if (r != kIgnored) kept.push_back(r);
      values.reserve(static_cast<std::size_t>(lines - first_point + 1) * kept.size());
    }
    if (words.size() != roles.size())
      refuse(text.number(), std::to_string(words.size()) + " columns, not " +
                              std::to_string(roles.size()) + " as " +
                              (by_header ? "its header names" :
                                           "line " + std::to_string(first_point) + " has"));
    for (std::size_t c = 0; c < words.size(); ++c) {
      if (roles[c] == kIgnored) continue;
      if (!parseNumber(words[c], number))
        refuse(text.number(), "column " + std::to_string(c + 1) + ", '" +
                                std::string(words[c].substr(0, 40)) + "', is not a number");
      values.push_back(static_cast<float>(number));
    }
  }
  if (first_point == 0) throw InputError(path + ": the file has no points");

  const std::size_t stride = kept.size(), count = values.size() / stride;
  // Of the points, the part whose three kept values from `offset` on have length 1 +- 1e-2.
  const auto unit_share = [&](std::size_t offset) {
    std::size_t unit = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const float* v = &values[i * stride + offset];
      unit += std::abs(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1.0f) <= 1e-2f;
    }
    return static_cast<double>(unit) / static_cast<double>(count);
  };
  const auto relabel = [&](std::size_t at, Role first) {
    for (int k = 0; k < 3; ++k) kept[at + k] = static_cast<Role>(first + k);
  };
  if (!by_header && roles.size() == 6 && unit_share(3) < 0.99) relabel(3, kR);
  if (!by_header && roles.size() == 9 && unit_share(3) >= 0.99 && unit_share(6) < 0.99) {
    relabel(3, kNx);
    relabel(6, kR);
  }
  const bool normals = std::count(kept.begin(), kept.end(), kNx) > 0;
  const bool colours = std::count(kept.begin(), kept.end(), kR) > 0;
  float brightest = 0.0f;
  for (std::size_t k = 0; k < values.size(); ++k)
    if (kept[k % stride] >= kR) brightest = std::max(brightest, values[k]);
  const float colour_scale = brightest <= 1.0f ? 255.0f : 1.0f;

  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud;
  cloud.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    pcl::PointXYZRGBNormal& p = cloud[i];
    p.rgba = 0xff000000u;
    for (std::size_t k = 0; k < stride; ++k) {
      const float v = values[i * stride + k];
      const Role r = kept[k];
      if (r <= kZ) p.data[r] = v;
      else if (r <= kNz) p.data_n[r - kNx] = v;
      else  // NaN to 0
        (r == kR ? p.r : r == kG ? p.g : p.b) = static_cast<std::uint8_t>(
          v * colour_scale > 0.0f ? std::lround(std::min(v * colour_scale, 255.0f)) : 0);
    }
  }
  std::vector<float>().swap(values);

  AsciiPoints out;
  pcl::toPCLPointCloud2(cloud, out.points);
  auto& fields = out.points.fields;
  fields.erase(std::remove_if(fields.begin(), fields.end(),
                              [&](const pcl::PCLPointField& f) {
                                return (!colours && f.name == "rgb") ||
                                       (!normals && f.name.rfind("normal_", 0) == 0) ||
                                       f.name == "curvature";
                              }),
               fields.end());
  for (std::size_t c = 0, k = 0; c < roles.size(); ++c) {
    const Role r = roles[c] == kIgnored ? kIgnored : kept[k++];
    out.columns += (c ? " " : "") + std::string(r == kIgnored ? "_" : kRoleNames[r]);
  }
  out.columns += by_header ? ", named by its header" : ", by their count";
  return out;
}

}  // namespace sss
