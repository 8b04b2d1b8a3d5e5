// png_test.cpp — PNG files at every level decode to the pixels they were given, by two decoders
// (stb_image through readPng, and libdeflate's strict inflate of the IDAT stream); the run-only
// coder's Huffman codes stay within deflate's limits; and FrameWriter writes every queued frame
// or reports the first failure.
#include "image/deflate_runs.h"
#include "phongvk/errors.h"
#include "tools/frame_writer.h"
#include "phongvk/image.h"
#include "phongvk/phongvk.h"
#include "test_util.h"

#include <libdeflate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>

namespace phongvk {
namespace {

using test::makeTempDir;
using test::thrownMessage;

Image filled(int w, int h, const std::function<void(int, int, uint8_t*)>& pixel) {
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) pixel(x, y, image.pixel(x, y));
  }
  return image;
}

Image noise(int w, int h, uint32_t seed) {
  std::mt19937 random(seed);
  return filled(w, h, [&](int, int, uint8_t* p) {
    for (int c = 0; c < 3; ++c) p[c] = uint8_t(random());
  });
}

// Smooth shading with flat stretches and steps, like a rendered frame.
Image shaded(int w, int h) {
  return filled(w, h, [&](int x, int y, uint8_t* p) {
    const bool inside = (x - w / 2) * (x - w / 2) + (y - h / 2) * (y - h / 2) < (w * h) / 8;
    p[0] = inside ? uint8_t(40 + x * 150 / w) : 20;
    p[1] = inside ? uint8_t(30 + y * 200 / h) : 20;
    p[2] = inside ? uint8_t((x + y) / 3) : 30;
  });
}

// A frame of the paper's scene at a small size, from the reference.
Image renderedFrame() {
  Renderer cpu(Backend::Cpu);
  return cpu.render(loadScene(test::sourcePath("scenes/paper/fig3_two_lights.json")).withImageSize(320, 213));
}

struct Chunk {
  std::string type;
  std::vector<uint8_t> data;
};

uint32_t bigEndian(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

// The chunks of a PNG, each CRC checked.
std::vector<Chunk> chunks(const std::vector<uint8_t>& png) {
  const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  EXPECT_TRUE(png.size() >= 8 && std::equal(signature, signature + 8, png.begin()));
  std::vector<Chunk> out;
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t length = bigEndian(&png[at]);
    EXPECT_LE(at + 12 + length, png.size());
    if (at + 12 + length > png.size()) break;
    Chunk chunk{std::string(png.begin() + ptrdiff_t(at) + 4, png.begin() + ptrdiff_t(at) + 8),
                std::vector<uint8_t>(png.begin() + ptrdiff_t(at) + 8, png.begin() + ptrdiff_t(at + 8 + length))};
    EXPECT_EQ(bigEndian(&png[at + 8 + length]), uint32_t(libdeflate_crc32(0, &png[at + 4], length + 4))) << chunk.type;
    out.push_back(std::move(chunk));
    at += 12 + length;
  }
  return out;
}

// The image's pixels from its IDAT stream, inflated by libdeflate (which rejects any stream that
// breaks RFC 1950/1951) and unfiltered ("Sub" on every row).
Image inflated(const std::vector<uint8_t>& png) {
  std::vector<uint8_t> stream;
  int width = 0, height = 0;
  for (const Chunk& chunk : chunks(png)) {
    if (chunk.type == "IHDR") {
      width = int(bigEndian(&chunk.data[0]));
      height = int(bigEndian(&chunk.data[4]));
      EXPECT_EQ(std::vector<uint8_t>(chunk.data.begin() + 8, chunk.data.end()), (std::vector<uint8_t>{8, 2, 0, 0, 0}));
    }
    if (chunk.type == "IDAT") stream.insert(stream.end(), chunk.data.begin(), chunk.data.end());
  }
  const size_t rowBytes = size_t(width) * 3;
  std::vector<uint8_t> filtered((rowBytes + 1) * size_t(height));
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  size_t got = 0;
  const auto result = libdeflate_zlib_decompress(inflater, stream.data(), stream.size(), filtered.data(), filtered.size(), &got);
  libdeflate_free_decompressor(inflater);
  EXPECT_EQ(result, LIBDEFLATE_SUCCESS);
  EXPECT_EQ(got, filtered.size());
  Image image(width, height);
  for (size_t y = 0; y < size_t(height); ++y) {
    const uint8_t* row = &filtered[y * (rowBytes + 1)];
    EXPECT_EQ(row[0], 1) << "row " << y << " is not filtered Sub";
    uint8_t* out = image.rgb.data() + y * rowBytes;
    for (size_t i = 0; i < rowBytes; ++i) out[i] = uint8_t(row[1 + i] + (i >= 3 ? out[i - 3] : 0));
  }
  return image;
}

void expectSamePixels(const Image& a, const Image& b, const std::string& what) {
  EXPECT_EQ(a.width, b.width) << what;
  EXPECT_EQ(a.height, b.height) << what;
  EXPECT_TRUE(a.rgb == b.rgb) << what;
}

TEST(Png, EveryLevelDecodesToTheSamePixelsByTwoDecoders) {
  const std::string dir = makeTempDir();
  const std::vector<std::pair<std::string, Image>> images = {
      {"1x1", noise(1, 1, 1)},
      {"one row", shaded(1000, 1)},
      {"one column", shaded(1, 700)},
      {"noise (no runs)", noise(97, 61, 2)},
      {"flat", filled(300, 200, [](int, int, uint8_t* p) { p[0] = 7, p[1] = 200, p[2] = 7; })},
      {"shaded", shaded(331, 257)},
      {"rows wider than deflate's window", shaded(11000, 3)},
      {"rendered", renderedFrame()},
  };
  for (const auto& [name, image] : images) {
    for (int level = PNG_LEVEL_MIN; level <= PNG_LEVEL_MAX; ++level) {
      const std::string what = name + " at level " + std::to_string(level);
      const std::vector<uint8_t> png = encodePng(image, level);
      expectSamePixels(inflated(png), image, what + " (libdeflate)");
      const std::string path = dir + "/out.png";
      writePng(path, image, level);
      expectSamePixels(readPng(path), image, what + " (stb_image)");
    }
  }
}

TEST(Png, SameImageSameBytesAndAnEncoderReusedAcrossSizesMatchesAFreshOne) {
  PngEncoder reused(PNG_LEVEL_RUNS);
  for (const Image& image : {shaded(200, 150), noise(31, 17, 3), shaded(640, 480), shaded(200, 150)}) {
    const std::vector<uint8_t> bytes = reused.encode(image);
    EXPECT_EQ(bytes, encodePng(image, PNG_LEVEL_RUNS));
    EXPECT_EQ(bytes, encodePng(image));  // the default level
  }
}

TEST(Png, RunsCompressARenderedFrameAndLevelsTradeSizeAsDocumented) {
  const Image frame = renderedFrame();
  const size_t stored = encodePng(frame, 0).size(), runs = encodePng(frame, 1).size();
  const size_t fast = encodePng(frame, 2).size(), smallest = encodePng(frame, 12).size();
  EXPECT_GT(stored, frame.rgb.size());  // stored: every byte, plus the filter bytes and framing
  EXPECT_LT(runs * 5, stored);
  EXPECT_LT(smallest, fast);
  EXPECT_LT(fast, runs);
}

TEST(Png, BadLevelAndMismatchedImageAreRejected) {
  EXPECT_EQ(thrownMessage<ArgumentError>([] { PngEncoder encoder(13); }),
            "PNG level 13 is out of range: 0 (no compression) to 12 (smallest files)");
  EXPECT_EQ(thrownMessage<ArgumentError>([] { encodePng(Image(), -1); }),
            "PNG level -1 is out of range: 0 (no compression) to 12 (smallest files)");
  Image broken(4, 4);
  broken.rgb.pop_back();
  EXPECT_EQ(thrownMessage<ArgumentError>([&] { encodePng(broken); }),
            "cannot encode a 4x4 image holding 47 bytes as PNG");
  const std::string dir = makeTempDir();
  EXPECT_EQ(thrownMessage<OutputError>([&] { writePng(dir + "/x.png", broken); }),
            "cannot write '" + dir + "/x.png': cannot encode a 4x4 image holding 47 bytes as PNG");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

// Sum over codes of 2^-length: exactly 1 for a complete prefix code.
double kraftSum(const std::vector<uint8_t>& lengths) {
  double sum = 0;
  for (uint8_t length : lengths) {
    if (length != 0) sum += std::ldexp(1.0, -length);
  }
  return sum;
}

TEST(DeflateRuns, HuffmanLengthsAreCompleteWithinTheLimitAndDeterministic) {
  // Fibonacci frequencies make the unlimited code 40 levels deep.
  std::vector<uint32_t> fibonacci(40);
  fibonacci[0] = fibonacci[1] = 1;
  for (size_t i = 2; i < fibonacci.size(); ++i) fibonacci[i] = fibonacci[i - 1] + fibonacci[i - 2];
  std::mt19937 random(5);
  std::vector<uint32_t> skewed(286);
  for (uint32_t& f : skewed) f = (random() % 4 == 0) ? 0 : uint32_t(1) << (random() % 24);
  for (const auto& [frequencies, limit] : {std::pair{fibonacci, 15}, std::pair{fibonacci, 7}, std::pair{skewed, 15}}) {
    const std::vector<uint8_t> lengths = huffmanLengths(frequencies, limit);
    EXPECT_DOUBLE_EQ(kraftSum(lengths), 1.0);
    EXPECT_LE(*std::max_element(lengths.begin(), lengths.end()), limit);
    for (size_t s = 0; s < frequencies.size(); ++s) EXPECT_EQ(lengths[s] != 0, frequencies[s] != 0) << s;
    EXPECT_EQ(lengths, huffmanLengths(frequencies, limit));
  }
  // Fewer than two symbols still make a complete code of two (an inflater rejects less).
  for (const std::vector<uint32_t>& few : {std::vector<uint32_t>(19, 0), std::vector<uint32_t>{0, 0, 9, 0}}) {
    const std::vector<uint8_t> lengths = huffmanLengths(few, 7);
    EXPECT_EQ(std::count(lengths.begin(), lengths.end(), 1), 2);
    EXPECT_DOUBLE_EQ(kraftSum(lengths), 1.0);
  }
}

TEST(FrameWriter, WritesEveryFrameWithSpareImagesToReuse) {
  const std::string dir = makeTempDir();
  std::set<int> reported;
  {
    FrameWriter writer(3, 2, PNG_LEVEL_RUNS, [&](const FrameFile& frame) { reported.insert(frame.index); });
    for (int i = 0; i < 20; ++i) {
      Image image = writer.spareImage();
      image = shaded(64 + i, 48);
      writer.push({i, dir + "/f" + std::to_string(i) + ".png", std::move(image)});
    }
    writer.finish();
    EXPECT_EQ(reported.size(), 20u);
    EXPECT_GT(writer.spareImage().rgb.capacity(), 0u);
  }
  for (int i = 0; i < 20; ++i) expectSamePixels(readPng(dir + "/f" + std::to_string(i) + ".png"), shaded(64 + i, 48), "frame");
}

TEST(FrameWriter, AFailedWriteIsRethrownNamingTheFileAndStopsTheRest) {
  const std::string dir = makeTempDir();
  FrameWriter writer(2, 2, PNG_LEVEL_RUNS);
  const std::string missing = dir + "/no such folder/f.png";
  writer.push({0, missing, shaded(32, 32)});
  const std::string message = thrownMessage<OutputError>([&] {
    for (int i = 1; i < 1000; ++i) writer.push({i, dir + "/f" + std::to_string(i) + ".png", shaded(32, 32)});
    writer.finish();
  });
  EXPECT_EQ(message, "cannot write '" + missing + "': folder '" + std::filesystem::path(missing).parent_path().string() + "' does not exist");
  EXPECT_EQ(thrownMessage<OutputError>([&] { writer.finish(); }), message);
}

TEST(FrameWriter, DestroyedWithFramesQueuedWritesThemFirst) {
  const std::string dir = makeTempDir();
  {
    FrameWriter writer(1, 8, 6);
    for (int i = 0; i < 8; ++i) writer.push({i, dir + "/f" + std::to_string(i) + ".png", shaded(100, 80)});
  }
  for (int i = 0; i < 8; ++i) EXPECT_TRUE(std::filesystem::exists(dir + "/f" + std::to_string(i) + ".png")) << i;
}

TEST(FrameWriter, BadLevelThrowsBeforeAnyThreadStarts) {
  EXPECT_THROW(FrameWriter(2, 2, 99), ArgumentError);
}

}  // namespace
}  // namespace phongvk
