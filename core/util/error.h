#pragma once
// Errors that reach the user. Every bad input becomes an InputError whose what() is one line
// naming the file and the problem; the CLI maps it to exit code 3, the GUI to a message box.
#include <stdexcept>
#include <string>

namespace tunnelmap {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& problem)
      : std::runtime_error(file.empty() ? problem : file + ": " + problem),
        file_(file), problem_(problem) {}
  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  std::string problem_;
};

// A parameter or option that is out of range or unknown (CLI exit code 2 when from the
// command line, 3 when from a preset file).
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An output that cannot be written as asked, found before any work: an output that
// is a device, a FIFO or a folder, an output that is also an input, two outputs on one path.
// A kind of ParameterError so that every front end reports it as bad usage (CLI exit code 2).
class OutputPathError : public ParameterError {
 public:
  OutputPathError(const std::string& file, const std::string& problem) : ParameterError(file + ": " + problem) {}
};

}  // namespace tunnelmap
