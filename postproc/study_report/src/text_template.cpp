// Named text blocks with {{placeholders}} (text_template.hpp).
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/post/study_report/text_template.hpp>

namespace fs = std::filesystem;

namespace brash::post::study_report {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// "=== name ===" -> name; empty for any other line.
std::string block_name(const std::string& line) {
  const std::string t = trim(line);
  if (t.size() < 8 || t.rfind("===", 0) != 0 || t.compare(t.size() - 3, 3, "===") != 0) return "";
  return trim(t.substr(3, t.size() - 6));
}

// A block's lines as paragraphs: the lines of each joined with a space, paragraphs with a blank line.
std::string paragraphs(const std::vector<std::string>& lines) {
  std::string text, paragraph;
  const auto close_paragraph = [&] {
    if (paragraph.empty()) return;
    text += (text.empty() ? "" : "\n\n") + paragraph;
    paragraph.clear();
  };
  for (const auto& line : lines) {
    const std::string t = trim(line);
    if (t.empty())
      close_paragraph();
    else
      paragraph += (paragraph.empty() ? "" : " ") + t;
  }
  close_paragraph();
  return text;
}

std::string names_of(const TextValues& values) {
  std::string names;
  for (const auto& [name, value] : values) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

}  // namespace

TextTemplate TextTemplate::load(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the text template (--template)", path.string()));
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

TextTemplate TextTemplate::parse(const std::string& text, const fs::path& source) {
  TextTemplate t;
  t.source_ = source;
  std::istringstream in(text);
  std::string line, current;
  std::vector<std::string> lines;
  int lineno = 0;
  const auto close_block = [&] {
    if (!current.empty()) t.blocks_[current] = paragraphs(lines);
    lines.clear();
  };
  while (std::getline(in, line)) {
    ++lineno;
    if (line.rfind('#', 0) == 0) continue;
    if (const std::string name = block_name(line); !name.empty()) {
      close_block();
      if (t.blocks_.count(name))
        throw InputError(fmt::format("{}:{}: block '{}' defined twice", source.string(), lineno, name));
      current = name;
    } else if (current.empty() && !trim(line).empty()) {
      throw InputError(fmt::format("{}:{}: text before the first block (a line '=== name ===')", source.string(),
                                   lineno));
    } else {
      lines.push_back(line);
    }
  }
  close_block();
  return t;
}

std::string TextTemplate::fill(const std::string& name, const TextValues& values) const {
  const auto block = blocks_.find(name);
  if (block == blocks_.end())
    throw InputError(fmt::format("{}: no block '=== {} ===' (brash-study-report needs it)", source_.string(), name));
  const std::string& text = block->second;
  std::string out;
  std::size_t at = 0;
  for (std::size_t open; (open = text.find("{{", at)) != std::string::npos;) {
    const std::size_t close = text.find("}}", open + 2);
    if (close == std::string::npos)
      throw InputError(fmt::format("{}: block '{}': '{{{{' without its '}}}}'", source_.string(), name));
    const std::string placeholder = trim(text.substr(open + 2, close - open - 2));
    const auto value = values.find(placeholder);
    if (value == values.end())
      throw InputError(fmt::format("{}: block '{}' uses the placeholder {{{{{}}}}}, which the tool does not fill "
                                   "there (it fills: {})",
                                   source_.string(), name, placeholder, names_of(values)));
    out += text.substr(at, open - at) + value->second;
    at = close + 2;
  }
  return out + text.substr(at);
}

}  // namespace brash::post::study_report
