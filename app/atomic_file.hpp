#pragma once
// Every file the app writes itself goes through here, so a reader (or an
// interrupted run) never sees half a file: the text goes into
// `<file>.tmp-<pid>` next to it, which replaces `file` by rename only once
// complete. Report folders are written whole the same way by report_writer.
#include <filesystem>
#include <string_view>

namespace spiral::app {

/// Throws std::runtime_error naming `file`; the temporary file is removed and
/// an existing `file` left untouched. The folder must exist.
void write_file_atomically(const std::filesystem::path& file, std::string_view text);

}  // namespace spiral::app
