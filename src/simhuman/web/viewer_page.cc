#include "simhuman/web/viewer_page.h"

#include <string_view>

#include "simhuman/core/check.h"
#include "simhuman/web/scene_view.h"

// The page's files, linked in by the assembler (paths from CMakeLists.txt); each is followed
// by its end symbol. `.incbin` keeps megabytes of JavaScript out of the C++ compiler.
#define SIMHUMAN_WEB_ASSET(name, path)                                                             \
  asm(".pushsection .rodata\n.balign 16\n.global " #name "_begin\n.hidden " #name "_begin\n" #name \
      "_begin:\n.incbin \"" path "\"\n.global " #name "_end\n.hidden " #name "_end\n" #name        \
      "_end:\n.popsection\n");                                                                     \
  extern "C" const char name##_begin[];                                                            \
  extern "C" const char name##_end[];

SIMHUMAN_WEB_ASSET(simhuman_web_three, SIMHUMAN_WEB_THREE_JS)
SIMHUMAN_WEB_ASSET(simhuman_web_orbit, SIMHUMAN_WEB_ORBIT_JS)
SIMHUMAN_WEB_ASSET(simhuman_web_html, SIMHUMAN_WEB_DIR "/viewer.html")
SIMHUMAN_WEB_ASSET(simhuman_web_viewer, SIMHUMAN_WEB_DIR "/viewer.js")

namespace simhuman::web {
namespace {

std::string_view Asset(const char* begin, const char* end) {
  return std::string_view(begin, static_cast<size_t>(end - begin));
}

}  // namespace

std::string ViewerPageHtml(const nlohmann::json& data) {
  const std::string_view html = Asset(simhuman_web_html_begin, simhuman_web_html_end);
  // the template's markers, in the order they appear, and what replaces each
  const std::string data_text = JsonForScript(data);
  const std::pair<std::string_view, std::string_view> parts[] = {
      {"/*SIMHUMAN_THREE*/", Asset(simhuman_web_three_begin, simhuman_web_three_end)},
      {"/*SIMHUMAN_ORBIT*/", Asset(simhuman_web_orbit_begin, simhuman_web_orbit_end)},
      {"/*SIMHUMAN_DATA*/", data_text},
      {"/*SIMHUMAN_VIEWER*/", Asset(simhuman_web_viewer_begin, simhuman_web_viewer_end)},
  };
  std::string out;
  out.reserve(html.size() + data_text.size() + 1200000);
  size_t pos = 0;
  for (const auto& [marker, text] : parts) {
    const size_t at = html.find(marker, pos);
    SH_CHECK(at != std::string_view::npos, "assets/web/viewer.html lacks a marker");
    out.append(html.substr(pos, at - pos));
    out.append(text);
    pos = at + marker.size();
  }
  out.append(html.substr(pos));
  return out;
}

}  // namespace simhuman::web
