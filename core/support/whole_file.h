// Files written whole or not at all: the bytes go to a temporary file beside the target, under
// a random name of its own, renamed onto it only once complete, so that a reader, or a process
// killed in the middle of a write, finds the old file, the new one or none.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace sss {

// Opens a temporary file beside `path` in binary mode, lets `fill` write into it, and renames
// it onto `path`. Throws std::runtime_error naming `path` when the file cannot be created, the
// stream fails, `fill` throws, or the rename fails; the temporary file is removed then.
void write_whole_file(const std::string& path, const std::function<void(std::ostream&)>& fill);

// The same for a writer that takes a file name (an image writer, say): `write` writes the file
// at the name it is given and returns false when it failed.
void write_whole_file_named(const std::string& path,
                            const std::function<bool(const std::string& temporary)>& write);

}  // namespace sss
