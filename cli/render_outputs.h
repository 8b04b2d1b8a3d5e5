// render_outputs.h — `phongvk render`'s files beside the colour image: --rgba (the colour with its
// coverage alpha), --depth and --ids (.png: 16-bit grey, .npy: NumPy arrays) and --normals (.png:
// 8-bit RGB normal map, .npy: float32 (height, width, 3)). Every check happens before rendering, and
// every file is written after it, by one process or by rank 0 of --mpi (render_mpi.cpp).
#pragma once

#include "cli/commands.h"

namespace phongvk::cli {

// The outputs the options ask the renderer for (none asked: all false). Throws UsageError for a
// --depth, --ids or --normals file that is neither .png nor .npy.
Outputs outputsAsked(const RenderOptions& options);

// Throws UsageError when two of -o, --depth, --ids and --normals name one file, when --ids FILE.png cannot hold the scene's object ids in 16 bits, and
// OutputError when a --depth, --ids or --normals file could not be written (checkWritable).
void checkOutputFiles(const RenderOptions& options, const Scene& scene);

// -o's image (RGBA with --rgba), then the --depth, --ids and --normals files.
void writeRenderedFiles(const RenderOptions& options, const RenderedFrame& frame);

}  // namespace phongvk::cli
