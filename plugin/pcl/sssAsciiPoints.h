// Text read line by line in bounded memory (ASCII point lists here, OBJ in sssPclLoading.cxx),
// and ASCII point lists as scanning tools (CloudCompare) export them: .xyz, .txt, .csv, .asc,
// one point a line, x y z with normals and colours after them.
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <cstddef>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace sss {

// The lines of a text file without their ends ("\n", "\r\n"), through a buffer of 1 MiB; a
// longer line is refused (InputError naming `shown` and the line's number).
class TextLines {
 public:
  TextLines(const std::string& shown, const std::string& path);
  bool next(std::string_view& line);  // false after the last line
  std::size_t number() const { return number_; }  // of the line `next` gave, from 1

 private:
  std::string shown_;
  std::ifstream in_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0, number_ = 0;
  bool read_all_ = false;
};

// The words of `line` between runs of any of `separators`.
void splitWords(std::string_view line, std::string_view separators,
                std::vector<std::string_view>& words);

// A whole word as a number ("1.5", "-2e3", "+4", "nan"); false when it is none.
bool parseNumber(std::string_view word, double& value);

struct AsciiPoints {
  pcl::PCLPointCloud2 points;  // x y z; normal_x, normal_y, normal_z and rgb when the file has them
  std::string columns;         // what the columns were read as, for a log line
};

// One point a line, numbers between spaces, tabs, commas or semicolons; lines starting with
// '#' or '//' are comments. A header line before the points that names x, y and z (commented,
// when it has as many words as the first point has numbers) names the columns: x y z, nx ny nz
// (or normal_x ...), r g b (or red green blue), any case, others ignored. Without one the
// column count says: 3 x y z; 4 x y z and a scalar (ignored); 6 x y z nx ny nz when the last
// three are unit vectors on 99 % of the lines, else x y z r g b; 7 x y z, an intensity
// (ignored), r g b (.pts); 9 x y z r g b nx ny nz (CloudCompare's order), or x y z nx ny nz
// r g b when only columns 4-6 are unit vectors. Colours are 0-1 when none is above 1, else
// 0-255. A first line of one whole number (a point count) is skipped. Throws InputError naming
// `path`, and the line when one is malformed.
AsciiPoints readAsciiPoints(const std::string& path, std::size_t cap, std::size_t point_bytes);

}  // namespace sss
