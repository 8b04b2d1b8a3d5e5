// output_file.h — writing an output file (a PNG) the way a user of a command expects: atomically
// into a regular file (a temporary file beside it, then a rename: nothing partial is ever left),
// through a symbolic link to the file it names, straight into a character device (-o /dev/null),
// to standard output for "-", and never replacing a device, FIFO or socket with a regular file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace phongvk {

// Writes `bytes` to `path` ("-": standard output). Every write is checked to the end, the close
// included; on any failure the temporary file is removed. Throws OutputError for a path that
// cannot take a file (checkOutputPath's reasons), OutputWriteError with the system's reason when
// writing fails (a full disk, a file-size limit, /dev/full).
void writeOutputFile(const std::string& path, const std::vector<uint8_t>& bytes);

// What checkWritable (image.h) checks: throws OutputError when `path` cannot take an output file.
void checkOutputPath(const std::string& path);

}  // namespace phongvk
