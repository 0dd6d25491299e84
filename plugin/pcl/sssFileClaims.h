// What a PCD or PLY header claims (points, fields, sizes), checked against the file and a
// memory cap before PCL allocates anything for it. A header that promises more data than the
// file holds, more than the cap, or that is not a header PCL can parse safely, is refused
// with one message naming the file, the claim and the size.
#pragma once

#include <cstddef>
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

}  // namespace sss
