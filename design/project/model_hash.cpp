#include "design/project/model_hash.hpp"

#include <fmt/format.h>

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <variant>
#include <vector>
#include <sstream>
#include <stdexcept>

namespace spiral::design {

std::uint64_t fnv1a_64(std::string_view bytes) {
  constexpr std::uint64_t kOffsetBasis = 14695981039346656037ULL;
  constexpr std::uint64_t kPrime = 1099511628211ULL;
  std::uint64_t hash = kOffsetBasis;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= kPrime;
  }
  return hash;
}

namespace {

std::string file_bytes(const std::filesystem::path& file, const char* what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read the {}", file.string(), what));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// The data files a project names, in a fixed order.
std::vector<std::filesystem::path> data_files(const Project& p) {
  std::vector<std::filesystem::path> files;
  if (const auto& h = p.hull.hydrodynamics) {
    if (!h->radiation_file.empty()) files.push_back(h->radiation_file);
    if (h->excitation_file) files.push_back(*h->excitation_file);
    if (h->rao_file) files.push_back(*h->rao_file);
  }
  if (p.hull.hydrostatics_file) files.push_back(*p.hull.hydrostatics_file);
  if (p.hull.mean_drift)
    if (const auto* drift = std::get_if<MeanDriftFile>(&*p.hull.mean_drift)) files.push_back(drift->file);
  if (p.hull.geometry && p.hull.geometry->panel_mesh) files.push_back(*p.hull.geometry->panel_mesh);
  return files;
}

}  // namespace

std::string model_hash(const std::filesystem::path& file) {
  return fmt::format("{:016x}", fnv1a_64(file_bytes(file, "project file")));
}

std::string project_content_hash(const std::filesystem::path& project_file, const Project& project) {
  // `extends` names where a variation's base is, which enters by its
  // content below: left out, a project and its base moved together (a clone
  // elsewhere, spiral run's iteration files, which extend by absolute path)
  // keep their hash and their stored results.
  const auto canonical_yaml = [](const std::filesystem::path& file) {
    YAML::Emitter canonical;
    try {
      YAML::Node tree = YAML::LoadFile(file.string());
      if (tree.IsMap()) tree.remove("extends");
      canonical << tree;
    } catch (const YAML::Exception& e) {
      throw std::runtime_error(fmt::format("{}: cannot read the project file: {}", file.string(), e.what()));
    }
    return std::string(canonical.c_str());
  };
  // Separators keep the parts apart; each data file enters with its name's
  // length and its size so that no two different sets hash alike by joining.
  // A variation's base files (`extends`) are part of its model.
  std::string content = canonical_yaml(project_file);
  for (const std::string& base : project.base_files) {
    content += '\x1d';
    content += canonical_yaml(base);
  }
  for (const std::filesystem::path& file : data_files(project)) {
    const std::string bytes = file_bytes(file, "data file");
    content += fmt::format("\x1e{}\x1f{}\x1f", file.filename().string(), bytes.size());
    content += bytes;
  }
  return fmt::format("{:016x}", fnv1a_64(content));
}

}  // namespace spiral::design
