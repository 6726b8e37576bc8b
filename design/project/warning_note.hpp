#pragma once
// Results carry free-text notes; one convention sets some apart: a note the
// engineer should act on (e.g. an all but undamped slow mode,
// design/analysis/dynamic_analysis.cpp) begins "warning: ". The CLI prints
// those as warnings and the reports as "Warning: …".

#include <string>
#include <string_view>

namespace spiral::design {

inline constexpr std::string_view kWarningPrefix = "warning: ";

/// A note that is a warning: `text` behind the prefix.
inline std::string warning_note(std::string_view text) { return std::string(kWarningPrefix) + std::string(text); }

inline bool is_warning(std::string_view note) { return note.starts_with(kWarningPrefix); }

/// A warning's text without the prefix; any other note as it is.
inline std::string_view note_text(std::string_view note) {
  return is_warning(note) ? note.substr(kWarningPrefix.size()) : note;
}

}  // namespace spiral::design
