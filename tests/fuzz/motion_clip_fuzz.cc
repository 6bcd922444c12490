// libFuzzer target: learn::ParseMotionClip on arbitrary bytes. A clip that parses must be valid,
// survive an exact round trip through its file form, and resample (as AMP does, to 30 Hz).
// Built with -DSIMHUMAN_FUZZ=ON (clang); run by scripts/fuzz_smoke.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "simhuman/learn/motion_clip.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace simhuman;
  std::string text(reinterpret_cast<const char*>(data), size);
  core::StatusOr<learn::MotionClip> clip = learn::ParseMotionClip(text, "fuzz.clip.json");
  if (!clip.ok()) return 0;
  if (!clip->Validate().ok()) std::abort();
  core::StatusOr<learn::MotionClip> again =
      learn::ParseMotionClip(learn::MotionClipToJson(*clip), "roundtrip.clip.json");
  if (!again.ok() || again->fps != clip->fps || again->source != clip->source ||
      again->frames.size() != clip->frames.size()) {
    std::abort();
  }
  for (size_t f = 0; f < clip->frames.size(); ++f) {
    const learn::ClipFrame &a = clip->frames[f], &b = again->frames[f];
    if (a.root_pos_m != b.root_pos_m || a.root_quat_wxyz != b.root_quat_wxyz ||
        a.q_rad != b.q_rad) {
      std::abort();
    }
  }
  // any status is fine; a crash, a hang or an invalid clip is a bug
  core::StatusOr<learn::MotionClip> resampled = learn::ResampleClip(*clip, 30);
  if (resampled.ok() && !resampled->Validate().ok()) std::abort();
  learn::SampleClip(*clip, 0.5 * clip->duration_s());
  return 0;
}
