#include "regression/golden_compare.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace spiral::golden {
namespace {

using nlohmann::json;

bool matches(const std::string& pattern, const std::string& text) {
  return ::fnmatch(pattern.c_str(), text.c_str(), 0) == 0;
}

const ToleranceRule* rule_for(const std::vector<ToleranceRule>& rules, const std::string& run,
                              const std::string& path) {
  for (const ToleranceRule& rule : rules)
    if (matches(rule.run, run) && matches(rule.path, path)) return &rule;
  return nullptr;
}

std::string kind_of(const json& value) {
  if (value.is_null()) return "null (NaN or Inf when written)";
  if (value.is_boolean()) return "boolean";
  if (value.is_number()) return "number";
  if (value.is_string()) return "string";
  if (value.is_array()) return "array";
  return "object";
}

std::string short_text(const json& value) {
  std::string text = value.dump();
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

class Comparer {
 public:
  Comparer(const std::string& run, const std::vector<ToleranceRule>& rules) : run_(run), rules_(rules) {}

  void compare(const json& actual, const json& baseline, const std::string& path) {
    const ToleranceRule* rule = rule_for(rules_, run_, path.empty() ? "/" : path);
    if (actual.is_null() && !baseline.is_null()) {
      fail(path, fmt::format("is null (NaN or Inf), baseline {}", short_text(baseline)));
      return;
    }
    if (rule && rule->ignore) return;
    const bool both_numbers = actual.is_number() && baseline.is_number();
    if (!both_numbers && actual.type() != baseline.type()) {
      fail(path, fmt::format("is {} {}, baseline {} {}", kind_of(actual), short_text(actual), kind_of(baseline),
                             short_text(baseline)));
      return;
    }
    if (actual.is_object()) {
      for (const auto& [key, value] : baseline.items()) {
        if (!actual.contains(key)) {
          fail(path + "/" + key, "missing (the baseline has it)");
          continue;
        }
        compare(actual.at(key), value, path + "/" + key);
      }
      for (const auto& [key, value] : actual.items())
        if (!baseline.contains(key)) fail(path + "/" + key, "extra key (not in the baseline)");
    } else if (actual.is_array()) {
      if (actual.size() != baseline.size()) {
        fail(path, fmt::format("has {} entries, baseline {}", actual.size(), baseline.size()));
        return;
      }
      for (std::size_t i = 0; i < actual.size(); ++i) compare(actual[i], baseline[i], fmt::format("{}/{}", path, i));
    } else if (both_numbers) {
      compare_numbers(actual.get<double>(), baseline.get<double>(), path, rule);
    } else if (actual != baseline) {
      fail(path, fmt::format("is {}, baseline {}", short_text(actual), short_text(baseline)));
    }
  }

  std::vector<Difference> differences;

 private:
  void compare_numbers(double actual, double baseline, const std::string& path, const ToleranceRule* rule) {
    if (!std::isfinite(actual)) {
      fail(path, fmt::format("is {} (not finite)", actual));
      return;
    }
    const double allowed =
        rule ? rule->absolute + rule->relative * std::max(std::abs(actual), std::abs(baseline)) : 0.0;
    const double off = std::abs(actual - baseline);
    if (off <= allowed) return;
    const std::string tolerance = rule ? fmt::format("rel {:g}, abs {:g}", rule->relative, rule->absolute)
                                       : std::string("no rule: must be exact");
    fail(path,
         fmt::format("is {:.12g}, baseline {:.12g} (off {:.3g}, allowed {:.3g}: {})", actual, baseline, off, allowed,
                     tolerance),
         rule ? rule->why : std::string());
  }

  void fail(const std::string& path, std::string message, std::string why = {}) {
    differences.push_back({path.empty() ? "/" : path, std::move(message), std::move(why)});
  }

  const std::string& run_;
  const std::vector<ToleranceRule>& rules_;
};

}  // namespace

std::vector<ToleranceRule> read_tolerance_rules(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot be read");
  json document;
  try {
    document = json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(file + ": " + e.what());
  }
  std::vector<ToleranceRule> rules;
  const json& list = document.at("rules");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& entry = list[i];
    ToleranceRule rule;
    rule.run = entry.value("run", "*");
    rule.path = entry.value("path", "*");
    rule.ignore = entry.value("ignore", false);
    rule.relative = entry.value("rel", 0.0);
    rule.absolute = entry.value("abs", 0.0);
    rule.why = entry.value("why", "");
    if (rule.why.empty()) throw std::runtime_error(fmt::format("{}: rules[{}] does not say why", file, i));
    if (rule.relative < 0.0 || rule.absolute < 0.0)
      throw std::runtime_error(fmt::format("{}: rules[{}] has a negative tolerance", file, i));
    rules.push_back(std::move(rule));
  }
  return rules;
}

std::vector<Difference> compare_documents(const nlohmann::json& actual, const nlohmann::json& baseline,
                                          const std::string& run, const std::vector<ToleranceRule>& rules) {
  Comparer comparer(run, rules);
  comparer.compare(actual, baseline, "");
  return comparer.differences;
}

}  // namespace spiral::golden
