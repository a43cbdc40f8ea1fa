// The document's title and how to read it (sections.hpp).
#include <fmt/format.h>

#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {

std::string section_header(const TextTemplate& text, const std::string& title, const std::string& manifest_name,
                           const std::string& study_command) {
  const std::string generated =
      study_command.empty()
          ? text.fill("header.generated", {{"manifest", manifest_name}})
          : text.fill("header.generated_rerun", {{"manifest", manifest_name}, {"study_command", study_command}});
  return fmt::format("# {}\n\n{}\n{}\n\n", title, generated, text.fill("header.legend"));
}

}  // namespace brash::post::study_report
