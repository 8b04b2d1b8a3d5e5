// png_check.h — whether a PNG file on disk is whole, so `phongvk sequence --resume` renders again
// only the frames that are missing or damaged.
#pragma once

#include <string>

namespace phongvk {

// Whether `path` is a regular file holding a whole PNG of width x height: the signature, an IHDR of
// that size first, every chunk's CRC right, and the IEND chunk last, at the end of the file (a file
// cut short lacks it; one zeroed or overwritten in the middle fails a CRC). phongvk writes every
// PNG whole (a temporary file, then a rename), so a frame that fails this came from elsewhere, from
// another size, or was damaged since. Reads the file once; decodes no pixels.
bool pngIsComplete(const std::string& path, int width, int height);

}  // namespace phongvk
