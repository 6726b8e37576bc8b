// golden_check: runs one whole `spiral` command and compares its JSON
// document with the stored baseline (tests/regression/baselines/NAME.json)
// under the named tolerances of tests/regression/tolerances.json.
//
//   golden_check --name NAME --baseline FILE --rules FILE [--document FILE]
//                [--exit CODE] -- SPIRAL ARGS...
//
// `{out}` in ARGS is replaced by a fresh temporary folder; --document names
// the file the command writes there (default: its standard output). The
// source folder and the temporary folder are written as `<source>` and
// `<out>` in every string, so a baseline does not depend on where the
// repository is checked out. With SPIRAL_GOLDEN_UPDATE=1 in the environment
// the document is written as the new baseline instead (scripts/update-baselines.sh).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "regression/golden_compare.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Arguments {
  std::string name, baseline, rules, document;
  int expected_exit = 0;
  std::vector<std::string> command;
};

Arguments parse(int argc, char** argv) {
  Arguments a;
  int i = 1;
  for (; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--") break;
    if (i + 1 >= argc) throw std::runtime_error(flag + ": value missing");
    const std::string value = argv[++i];
    if (flag == "--name")
      a.name = value;
    else if (flag == "--baseline")
      a.baseline = value;
    else if (flag == "--rules")
      a.rules = value;
    else if (flag == "--document")
      a.document = value;
    else if (flag == "--exit")
      a.expected_exit = std::stoi(value);
    else
      throw std::runtime_error("unknown flag " + flag);
  }
  for (++i; i < argc; ++i) a.command.emplace_back(argv[i]);
  if (a.name.empty() || a.baseline.empty() || a.rules.empty() || a.command.empty())
    throw std::runtime_error("usage: golden_check --name N --baseline F --rules F [--document F] [--exit C] -- CMD...");
  return a;
}

std::string shell_word(const std::string& word) {
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
    text.replace(at, from.size(), to);
}

/// Pretty-printed with every array of plain values on one line: a baseline
/// diff then reads channel by channel, and the files stay a third the size.
void write_baseline(std::ostream& out, const json& value, int depth) {
  const auto scalar_array = [](const json& v) {
    return v.is_array() && std::none_of(v.begin(), v.end(), [](const json& x) { return x.is_structured(); });
  };
  if (!value.is_structured() || scalar_array(value)) {
    out << value.dump();
    return;
  }
  const std::string indent(static_cast<std::size_t>(depth + 1), ' ');
  const bool object = value.is_object();
  out << (object ? "{" : "[");
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    out << (first ? "\n" : ",\n") << indent;
    if (object) out << json(it.key()).dump() << ": ";
    write_baseline(out, *it, depth + 1);
    first = false;
  }
  out << "\n" << std::string(static_cast<std::size_t>(depth), ' ') << (object ? "}" : "]");
}

void normalize_strings(json& value, const std::string& source, const std::string& out) {
  if (value.is_string()) {
    std::string text = value.get<std::string>();
    replace_all(text, out, "<out>");
    replace_all(text, source, "<source>");
    value = text;
  } else if (value.is_structured()) {
    for (auto& item : value) normalize_strings(item, source, out);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Arguments a = parse(argc, argv);
    const fs::path out = fs::temp_directory_path() / fmt::format("spiral-golden-{}-{}", a.name, ::getpid());
    fs::remove_all(out);
    fs::create_directories(out);

    std::string command;
    for (std::string word : a.command) {
      replace_all(word, "{out}", out.string());
      command += shell_word(word) + " ";
    }
    const fs::path stdout_file = out / "stdout.txt", stderr_file = out / "stderr.txt";
    command += fmt::format(">{} 2>{} </dev/null", shell_word(stdout_file.string()), shell_word(stderr_file.string()));
    const int status = std::system(command.c_str());
    const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (exit_code != a.expected_exit) {
      std::cerr << fmt::format("{}: exit {} (expected {})\n{}\n{}", a.name, exit_code, a.expected_exit, command,
                               read_text(stderr_file));
      return 1;
    }

    const fs::path document_file = a.document.empty() ? stdout_file : out / a.document;
    json document = json::parse(read_text(document_file));
    normalize_strings(document, SPIRAL_SOURCE_DIR, out.string());
    fs::remove_all(out);

    const char* update = std::getenv("SPIRAL_GOLDEN_UPDATE");
    if (update && std::string(update) == "1") {
      fs::create_directories(fs::path(a.baseline).parent_path());
      std::ofstream file(a.baseline);
      write_baseline(file, document, 0);
      file << "\n";
      std::cout << a.name << ": baseline written to " << a.baseline << "\n";
      return 0;
    }
    if (!fs::exists(a.baseline)) {
      std::cerr << a.name << ": no baseline at " << a.baseline << " (scripts/update-baselines.sh writes it)\n";
      return 1;
    }
    const json baseline = json::parse(read_text(a.baseline));
    const auto rules = spiral::golden::read_tolerance_rules(a.rules);
    const auto differences = spiral::golden::compare_documents(document, baseline, a.name, rules);
    if (differences.empty()) {
      std::cout << a.name << ": matches its baseline\n";
      return 0;
    }
    std::cerr << fmt::format("{}: {} difference(s) from {}\n", a.name, differences.size(), a.baseline);
    for (std::size_t i = 0; i < differences.size() && i < 40; ++i)
      std::cerr << "  " << differences[i].path << ": " << differences[i].message << "\n";
    if (differences.size() > 40) std::cerr << "  ... and " << differences.size() - 40 << " more\n";
    std::vector<std::string> whys;
    for (const auto& d : differences)
      if (!d.why.empty() && std::find(whys.begin(), whys.end(), d.why) == whys.end()) whys.push_back(d.why);
    for (const std::string& why : whys) std::cerr << "tolerance exceeded: " << why << "\n";
    std::cerr << "If the change is intended, run scripts/update-baselines.sh and say why in the commit.\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "golden_check: " << e.what() << "\n";
    return 1;
  }
}
