#pragma once
/// `simhuman export RUN_DIR [--bvh out.bvh] [--gltf out.glb] [--agent N] [--fps R]
/// [--video out.mp4] [--sheet out.png] [--shadows] [--fixed-camera]`: a finished run (the --out
/// folder of `simhuman run`) as BVH motion of the humans, an animated glTF scene
/// (docs/FORMATS.md "BVH export", "glTF export"), or a video and contact sheet rendered again
/// with today's camera.

#include <ostream>
#include <string>
#include <vector>

namespace simhuman::app {

/// The flags of `simhuman export`.
struct ExportRunFlags {
  std::string run_dir;
  std::string bvh;       ///< BVH output; with several humans and no --agent, one file per human
  std::string gltf;      ///< .glb output
  int agent = -1;        ///< only this human's BVH (-1: every human)
  double fps = 0;        ///< sample rate (0: the run's recording rate)
  std::string video;     ///< MP4 re-rendered from the trajectory (needs the run's plan.json)
  std::string sheet;     ///< contact sheet PNG, likewise
  bool shadows = false;  ///< video/sheet: shadows from the scene's lights
  bool fixed_camera = false;  ///< video/sheet: the fixed side-front camera of earlier versions
};

/// BVH file names for `path` with `num_humans` humans: the path itself for one human, else
/// "<stem>_h<k><ext>" for each human k (out.bvh -> out_h0.bvh, out_h1.bvh).
std::vector<std::string> BvhPaths(const std::string& path, int num_humans);

/// Runs `simhuman export`. Exit codes as `run` (2: a missing or malformed run folder, bad
/// flags; 1: an output that cannot be written).
int ExportRunCommand(const ExportRunFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
