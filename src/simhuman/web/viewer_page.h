#pragma once
/// The one web page of simhuman's viewer (assets/web/viewer.html and viewer.js), with three.js
/// r111 and its OrbitControls from Debian's libjs-three linked into the binary at build time:
/// the page needs no network. The replay file and the live server serve the same page.

#include <nlohmann/json.hpp>
#include <string>

namespace simhuman::web {

/// The page with everything inlined and `data` as window.SIMHUMAN_DATA. `data["mode"]` is
/// "replay" (data also holds "scene", "steps", "replay": see docs/FORMATS.md) or "live" (the
/// page fetches the scene from the server's /api/scene and streams /api/events).
std::string ViewerPageHtml(const nlohmann::json& data);

}  // namespace simhuman::web
