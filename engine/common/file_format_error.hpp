#pragma once
// The exception the engine's file readers throw for a file that cannot be read
// or does not follow its format. It carries the file name and the 1-based line
// number so that the message points the user at the offending line
// (STYLE.md rule 9: context goes in the exception text).

#include <cstddef>
#include <stdexcept>
#include <string>

namespace spiral::engine {

class FileFormatError : public std::runtime_error {
 public:
  /// `line` is 1-based; 0 means the problem concerns the whole file (e.g. it
  /// cannot be opened), and the text then reads "file: message".
  FileFormatError(std::string file, std::size_t line, std::string message)
      : std::runtime_error(compose(file, line, message)),
        file_(std::move(file)),
        line_(line),
        message_(std::move(message)) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  /// The problem without the "file:line: " prefix.
  const std::string& message() const { return message_; }

 private:
  static std::string compose(const std::string& file, std::size_t line, const std::string& message) {
    return line == 0 ? file + ": " + message : file + ":" + std::to_string(line) + ": " + message;
  }

  std::string file_;
  std::size_t line_;
  std::string message_;
};

}  // namespace spiral::engine
