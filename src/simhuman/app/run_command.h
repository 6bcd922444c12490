#pragma once
/// `simhuman run`: one episode of a plan in a scene, with progress lines, a summary, result
/// files and an optional video.

#include <cstdint>
#include <ostream>
#include <string>

#include "simhuman/app/llm_flags.h"

namespace simhuman::app {

/// The flags of `simhuman run`.
struct RunFlags {
  std::string scene;                ///< built-in scene name or scene JSON file
  std::string plan;                 ///< plan file (this or `command`)
  std::string command;              ///< text command planned with `planner` (or `plan`)
  std::string planner = "offline";  ///< one of PlannerNames()
  LlmFlags llm;                     ///< --llm-* flags (with --planner llm)
  uint64_t seed = 1;
  std::string preset = "fast";
  bool preset_given = false;  ///< --preset was on the command line
  std::string config;         ///< MpcConfig JSON file; empty: the preset
  std::string out = "out";    ///< output folder
  bool video = false;
  bool html = false;      ///< also write DIR/replay.html (web/replay_html.h)
  double settle_s = 1.5;  ///< keep simulating this long after the last step completes
  /// Walking policy for get-close steps; empty: assets/policies/walk.pt when it exists.
  std::string policy;
  bool no_walk = false;  ///< never walk with a policy (MPC only)
  /// Carrying policy for carry steps; empty: assets/policies/carry.pt when it exists.
  std::string carry_policy;
  /// Tabletop plans (a seated human with a dexterous hand): grasp policy file or "scripted";
  /// empty: assets/policies/grasp.pt when it exists, else "scripted".
  std::string grasp_policy;
  std::string place_policy = "scripted";  ///< tabletop plans: a place policy file or "scripted"
  /// Tabletop plans: "truth" (the objects' true state) or "vision" (the head camera and
  /// `vision_model`, empty: assets/vision/vision.pt).
  std::string perception = "truth";
  std::string vision_model;
  /// "X,Y" or "X,Y,YAW_DEG": where the first human starts, standing (overrides the scene's).
  std::string start;
};

/// Runs the command. Writes DIR/result.json, DIR/trajectory.csv, DIR/scene.json and
/// DIR/plan.json, then with --html DIR/replay.html and with --video DIR/video.mp4 and
/// DIR/contact_sheet.png. Progress and the
/// summary go to `out`, errors (one line each) to `err`. Returns kExitOk when the episode ran
/// (whether or not the plan succeeded), kExitBadInput for bad input (detected before anything
/// is simulated or written), kExitInternal for internal and rendering failures (the results
/// are written before rendering starts).
int RunCommand(const RunFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
