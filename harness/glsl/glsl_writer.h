// Collects GLSL lines with two-space indentation.
#pragma once

#include <string>

namespace rayspec {

class GlslWriter {
 public:
  void line(const std::string& text) {
    if (!text.empty()) out_.append(2 * static_cast<size_t>(depth_), ' ').append(text);
    out_ += '\n';
  }
  void raw(const std::string& text) { out_ += text; }  // unindented, as is
  void open(const std::string& text) {
    line(text);
    ++depth_;
  }  // "... {"
  void close(const std::string& text = "}") {
    --depth_;
    line(text);
  }
  void reopen(const std::string& text) {
    --depth_;
    line(text);
    ++depth_;
  }  // "} else {"
  const std::string& text() const { return out_; }
  // A number no other call returns: unique names of helper variables.
  int nextId() { return next_id_++; }

 private:
  std::string out_;
  int depth_ = 0;
  int next_id_ = 0;
};

}  // namespace rayspec
