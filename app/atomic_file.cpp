#include "app/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <fmt/format.h>

namespace spiral::app {

void write_file_atomically(const std::filesystem::path& file, std::string_view text) {
  // The pid keeps two runs writing into the same folder off each other's temporary file.
  std::filesystem::path tmp = file;
  tmp += ".tmp-" + std::to_string(::getpid());
  std::error_code ec;
  {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
    out << text;
    out.close();
    if (!out) {
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error(fmt::format("error while writing {}", file.string()));
    }
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(fmt::format("cannot write {}", file.string()));
  }
}

}  // namespace spiral::app
