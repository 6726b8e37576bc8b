#pragma once
// A raster image in memory (8-bit RGB, top row first) and its PNG encoding.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace spiral::report {

/// A colour with components in [0, 1].
struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes, row-major, top row first

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}
  std::uint8_t* at(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
  const std::uint8_t* at(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

/// PNG bytes of the image (cairo's encoder: same image → same bytes).
std::vector<std::uint8_t> encode_png(const Image& image);

/// Writes the image as PNG. Throws std::runtime_error naming the file.
void write_png(const Image& image, const std::filesystem::path& file);

}  // namespace spiral::report
