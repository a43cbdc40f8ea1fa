// The study document's prose, read from a template file of named text blocks (templates/study.md.tmpl), so
// that the sentences which state what the numbers mean can be read and edited without touching C++.
//
// Format:
//   # a comment line (anywhere)
//   === block.name ===
//   Text of the block. {{placeholder}} is replaced by a value the tool computes (numbers come formatted).
//   Lines of a paragraph are joined with one space; a blank line starts a new paragraph.
// A block runs to the next "=== name ===" line. Headings, tables and number formats stay in the tool.
#pragma once
#include <filesystem>
#include <map>
#include <string>

namespace brash::post::study_report {

using TextValues = std::map<std::string, std::string>;  // placeholder name -> its text

class TextTemplate {
 public:
  // The blocks of the file at PATH; brash::InputError naming the file (and line) when it cannot be used.
  static TextTemplate load(const std::filesystem::path& path);
  // The blocks of TEXT, as if read from a file named SOURCE (for messages).
  static TextTemplate parse(const std::string& text, const std::filesystem::path& source);

  // Block NAME with each {{placeholder}} replaced by its value in VALUES; brash::InputError naming the template
  // file, the block and the placeholder when the block is missing or uses a placeholder VALUES lacks.
  std::string fill(const std::string& name, const TextValues& values = {}) const;

 private:
  std::filesystem::path source_;
  std::map<std::string, std::string> blocks_;  // name -> paragraphs joined by a blank line
};

}  // namespace brash::post::study_report
