#include "report/image.hpp"

#include <cairo.h>
#include <fmt/format.h>

#include <fstream>
#include <memory>
#include <stdexcept>

#include "report/cairo_image.hpp"

namespace spiral::report {

std::vector<std::uint8_t> encode_png(const Image& image) {
  const SurfacePtr surface = to_surface(image);
  std::vector<std::uint8_t> bytes;
  const auto status = cairo_surface_write_to_png_stream(
      surface.get(),
      [](void* closure, const unsigned char* data, unsigned int length) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(closure);
        out->insert(out->end(), data, data + length);
        return CAIRO_STATUS_SUCCESS;
      },
      &bytes);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error("PNG encoding failed");
  return bytes;
}

void write_png(const Image& image, const std::filesystem::path& file) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write the image", file.string()));
}

}  // namespace spiral::report
