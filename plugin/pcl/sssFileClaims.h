// What a PCD or PLY header claims (points, fields, sizes), or the lines of a text format (OBJ,
// ASCII point lists), checked against the file and a memory cap before anything is allocated
// for it. A header that promises more data than the
// file holds, more than the cap, or that is not a header PCL can parse safely, is refused
// with one message naming the file, the claim and the size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace sss {

// The default memory cap of a load: half the machine's physical memory.
std::size_t defaultMemoryCap();

// "1.5 GiB", "812 MiB", "4.0 KiB", "17 bytes".
std::string byteSize(double bytes);

// Throw InputError (sssPclLoading.h) naming `shown` (the path the user gave) when the PCD
// file at `path` has a header PCL cannot parse safely, claims more data than the file holds,
// or claims points that would need more than `cap` bytes held as PCL's blob plus a cloud of
// `point_bytes` per point.
void checkPcdClaims(const std::string& shown, const std::string& path, std::size_t cap,
                    std::size_t point_bytes);

// The same for a PLY file (ascii or binary, any elements; list properties count at least
// their length field). A mesh's faces count at least three indices each in memory.
void checkPlyClaims(const std::string& shown, const std::string& path, std::size_t cap,
                    std::size_t point_bytes);

// What an OBJ file's lines hold, counted without parsing them: v, vn and f lines, and the
// corners of the faces (their words).
struct ObjCounts {
  std::uint64_t vertices = 0, normals = 0, faces = 0, corners = 0;
};

// Throw InputError when the OBJ file's lines, parsed into a mesh and a cloud of `point_bytes`
// per vertex, would need more than `cap` bytes; else their counts.
ObjCounts checkObjClaims(const std::string& shown, const std::string& path, std::size_t cap,
                         std::size_t point_bytes);

// Throw InputError when a text file of one point a line could hold more points than fit in
// `cap` bytes (each line a point, held while parsed and as a cloud of `point_bytes`); else
// the number of its lines.
std::uint64_t checkPointListClaims(const std::string& shown, const std::string& path,
                                   std::size_t cap, std::size_t point_bytes);

}  // namespace sss
