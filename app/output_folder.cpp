#include "app/output_folder.hpp"

namespace spiral::app {

std::filesystem::path output_folder(const std::string& out, const std::string& project_file,
                                    const std::filesystem::path& leaf) {
  if (!out.empty()) return out;
  return std::filesystem::path("out") / std::filesystem::path(project_file).stem() / leaf;
}

}  // namespace spiral::app
