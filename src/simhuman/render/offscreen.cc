#include "simhuman/render/offscreen.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "simhuman/render/egl_context.h"

#ifndef GL_MAX_SAMPLES
#define GL_MAX_SAMPLES 0x8D57
#endif
#ifndef GL_MAX_RENDERBUFFER_SIZE
#define GL_MAX_RENDERBUFFER_SIZE 0x84E8
#endif

namespace simhuman::render {
namespace {

std::string GlString(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s != nullptr ? s : "";
}

// MuJoCo aborts the process (mju_error) when the GL context lacks what it needs, so check
// those requirements first and turn them into errors
absl::Status CheckGlRequirements() {
  const std::string version = GlString(GL_VERSION);
  int major = 0, minor = 0;
  if (std::sscanf(version.c_str(), "%d.%d", &major, &minor) != 2) {
    return absl::UnavailableError(
        absl::StrCat("cannot parse the OpenGL version string '", version, "'"));
  }
  if (major < 1 || (major == 1 && minor < 5)) {
    return absl::UnavailableError(
        absl::StrCat("MuJoCo needs OpenGL 1.5 or higher, the context has ", version));
  }
  const std::string extensions = " " + GlString(GL_EXTENSIONS) + " ";
  if (extensions.find(" GL_ARB_framebuffer_object ") == std::string::npos) {
    return absl::UnavailableError(
        absl::StrCat("MuJoCo needs GL_ARB_framebuffer_object, which the OpenGL context (", version,
                     ", renderer '", GlString(GL_RENDERER), "') lacks"));
  }
  return absl::OkStatus();
}

// the sky's colour for a view ray `elev_deg` above the horizon: pale at the horizon, deeper
// blue overhead; below the horizon (past the floor's edge) a hazy grey-blue
void SkyColour(double elev_deg, uint8_t* rgb) {
  constexpr double kHorizon[3] = {214, 226, 238}, kZenith[3] = {92, 142, 206};
  constexpr double kGround[3] = {178, 186, 196};
  const double t = std::clamp(elev_deg / 50.0, 0.0, 1.0);
  for (int k = 0; k < 3; ++k) {
    const double c = elev_deg < 0 ? kGround[k] + (kHorizon[k] - kGround[k]) *
                                                     std::clamp(1.0 + elev_deg / 3.0, 0.0, 1.0)
                                  : kHorizon[k] + (kZenith[k] - kHorizon[k]) * std::sqrt(t);
    rgb[k] = static_cast<uint8_t>(std::lround(c));
  }
}

// paints the sky where the depth buffer is at the far plane (`bottom_up`: OpenGL row order)
void PaintSky(const CameraSpec& cam, double fovy_deg, int width, int height,
              const std::vector<float>& depth, std::vector<uint8_t>* bottom_up) {
  const double tan_half = std::tan(0.5 * fovy_deg * M_PI / 180.0);
  for (int y = 0; y < height; ++y) {
    // row y counts from the bottom; its view ray's angle above the camera's axis
    const double v = (2.0 * (y + 0.5) / height - 1.0) * tan_half;
    const double elev = cam.elevation_deg + std::atan(v) * 180.0 / M_PI;
    uint8_t colour[3];
    SkyColour(elev, colour);
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (depth[i] < 1.0f) continue;
      std::memcpy(bottom_up->data() + 3 * i, colour, 3);
    }
  }
}

int AutoFontScale(int height) {
  if (height < 300) return mjFONTSCALE_50;
  if (height < 800) return mjFONTSCALE_100;
  if (height < 1200) return mjFONTSCALE_150;
  return mjFONTSCALE_200;
}

}  // namespace

absl::Status RendererOptions::Validate() const {
  if (!(fovy_deg == 0 || (fovy_deg >= 1 && fovy_deg <= 170))) {
    return absl::InvalidArgumentError(absl::StrCat("RendererOptions.fovy_deg is ", fovy_deg,
                                                   "; valid are 0 (the model's) or 1..170"));
  }
  if (msaa_samples < -1 || msaa_samples > 64) {
    return absl::InvalidArgumentError(
        absl::StrCat("RendererOptions.msaa_samples is ", msaa_samples,
                     "; valid are -1 (the model's offsamples) or 0..64"));
  }
  if (font_scale != 0 && font_scale != 50 && font_scale != 100 && font_scale != 150 &&
      font_scale != 200 && font_scale != 250 && font_scale != 300) {
    return absl::InvalidArgumentError(
        absl::StrCat("RendererOptions.font_scale is ", font_scale,
                     "; valid are 0 (auto), 50, 100, 150, 200, 250, 300"));
  }
  if (max_geoms < 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("RendererOptions.max_geoms is ", max_geoms, "; it must be >= 1"));
  }
  return absl::OkStatus();
}

absl::StatusOr<std::unique_ptr<OffscreenRenderer>> OffscreenRenderer::Create(
    const mjModel* m, int width, int height, const RendererOptions& options) {
  if (m == nullptr) return absl::InvalidArgumentError("OffscreenRenderer: model is null");
  if (width < 1 || height < 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("OffscreenRenderer: image size ", width, "x", height, " must be >= 1x1"));
  }
  if (absl::Status s = options.Validate(); !s.ok()) return s;

  std::unique_ptr<OffscreenRenderer> r(new OffscreenRenderer());
  r->width_ = width;
  r->height_ = height;
  r->options_ = options;
  r->owner_thread_ = std::this_thread::get_id();
  auto egl = EglContext::Create();
  if (!egl.ok()) return egl.status();
  r->egl_ = std::move(egl).value();

  if (absl::Status s = CheckGlRequirements(); !s.ok()) return s;
  GLint max_size = 0, max_samples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width > max_size || height > max_size) {
    return absl::InvalidArgumentError(absl::StrCat("OffscreenRenderer: image size ", width, "x",
                                                   height, " exceeds GL_MAX_RENDERBUFFER_SIZE ",
                                                   max_size, " of ", r->gl_renderer()));
  }

  mjv_defaultOption(&r->vis_options_);
  if (absl::Status s = r->LoadModel(m, max_samples); !s.ok()) return s;
  r->bottom_up_.resize(static_cast<size_t>(width) * height * 3);
  if (options.sky) r->depth_.resize(static_cast<size_t>(width) * height);
  return r;
}

absl::Status OffscreenRenderer::LoadModel(const mjModel* m, int max_samples) {
  // own a copy whose offscreen buffer matches the image
  model_ = mj_copyModel(nullptr, m);
  if (model_ == nullptr) {
    return absl::ResourceExhaustedError("OffscreenRenderer: mj_copyModel failed");
  }
  model_->vis.global.offwidth = width_;
  model_->vis.global.offheight = height_;
  int samples = options_.msaa_samples >= 0 ? options_.msaa_samples : model_->vis.quality.offsamples;
  if (options_.fovy_deg > 0) model_->vis.global.fovy = static_cast<float>(options_.fovy_deg);
  model_->vis.quality.offsamples = std::clamp(samples, 0, std::max<int>(max_samples, 0));

  // shadows need a light that casts them: every light of the snapshot does (before
  // mjr_makeContext, which reads the shadow settings once)
  if (options_.shadows) {
    for (int l = 0; l < model_->nlight; ++l) model_->light_castshadow[l] = 1;
  }
  mjv_defaultScene(&scene_);
  mjv_makeScene(model_, &scene_, options_.max_geoms);
  scene_made_ = true;
  mjr_defaultContext(&context_);
  const int font_scale = options_.font_scale > 0 ? options_.font_scale : AutoFontScale(height_);
  mjr_makeContext(model_, &context_, font_scale);
  context_made_ = true;
  mjr_setBuffer(mjFB_OFFSCREEN, &context_);
  if (context_.currentBuffer != mjFB_OFFSCREEN) {
    return absl::InternalError("OffscreenRenderer: MuJoCo could not select its offscreen buffer");
  }
  if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
    return absl::InternalError(absl::StrCat("OffscreenRenderer: OpenGL error 0x", absl::Hex(err),
                                            " while creating MuJoCo's render context on ",
                                            gl_renderer()));
  }
  return absl::OkStatus();
}

absl::Status OffscreenRenderer::SetModel(const mjModel* m) {
  if (m == nullptr) return absl::InvalidArgumentError("OffscreenRenderer::SetModel: model is null");
  if (std::this_thread::get_id() != owner_thread_) {
    return absl::FailedPreconditionError(
        "OffscreenRenderer::SetModel called from a thread other than the one that created the "
        "renderer");
  }
  if (absl::Status s = egl_->MakeCurrent(); !s.ok()) return s;
  if (context_made_) mjr_freeContext(&context_);
  if (scene_made_) mjv_freeScene(&scene_);
  if (model_ != nullptr) mj_deleteModel(model_);
  context_made_ = scene_made_ = false;
  model_ = nullptr;
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  return LoadModel(m, max_samples);
}

OffscreenRenderer::~OffscreenRenderer() {
  // GL objects can only be freed with our context current; if that fails (wrong thread) they
  // go with the context
  if (context_made_ && egl_ != nullptr && egl_->MakeCurrent().ok()) {
    mjr_freeContext(&context_);
  }
  if (scene_made_) mjv_freeScene(&scene_);
  if (model_ != nullptr) mj_deleteModel(model_);
  egl_.reset();
}

const std::string& OffscreenRenderer::egl_platform() const { return egl_->platform(); }

const std::string& OffscreenRenderer::gl_renderer() const { return egl_->gl_renderer(); }

absl::Status OffscreenRenderer::DrawScene(const mjData* d, const CameraSpec& cam, bool segment) {
  if (std::this_thread::get_id() != owner_thread_) {
    return absl::FailedPreconditionError(
        "OffscreenRenderer::Render called from a thread other than the one that created the "
        "renderer; OpenGL contexts are bound to their thread");
  }
  if (absl::Status s = egl_->MakeCurrent(); !s.ok()) return s;

  // the scene update only reads d (it writes d->warning when the scene is full)
  mjvCamera mjcam;
  ToMjvCamera(cam, &mjcam);
  mjv_updateScene(model_, const_cast<mjData*>(d), &vis_options_, nullptr, &mjcam, mjCAT_ALL,
                  &scene_);
  if (scene_.ngeom >= scene_.maxgeom) {
    return absl::ResourceExhaustedError(absl::StrCat(
        "OffscreenRenderer: the scene needs more than RendererOptions.max_geoms = ", scene_.maxgeom,
        " geoms; raise it"));
  }
  // the lit image, or each geom painted with its index (+1) for RenderBodyIds
  scene_.flags[mjRND_SHADOW] = !segment && options_.shadows ? 1 : 0;
  scene_.flags[mjRND_REFLECTION] = !segment && options_.reflections ? 1 : 0;
  scene_.flags[mjRND_SKYBOX] = !segment && options_.skybox ? 1 : 0;
  scene_.flags[mjRND_SEGMENT] = segment ? 1 : 0;
  scene_.flags[mjRND_IDCOLOR] = segment ? 1 : 0;
  const mjrRect viewport = {0, 0, width_, height_};
  mjr_setBuffer(mjFB_OFFSCREEN, &context_);
  mjr_render(viewport, &scene_, &context_);
  // rows of odd widths are not 4-byte aligned
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  return absl::OkStatus();
}

absl::Status OffscreenRenderer::Render(const mjData* d, const CameraSpec& cam,
                                       std::vector<uint8_t>* rgb, std::string_view caption) {
  if (d == nullptr || rgb == nullptr) {
    return absl::InvalidArgumentError("OffscreenRenderer::Render: data or output is null");
  }
  if (absl::Status s = DrawScene(d, cam, false); !s.ok()) return s;
  const mjrRect viewport = {0, 0, width_, height_};
  if (options_.sky) {
    // the sky goes under the caption: read, paint, draw back, then the caption
    mjr_readPixels(bottom_up_.data(), depth_.data(), viewport, &context_);
    PaintSky(cam, model_->vis.global.fovy, width_, height_, depth_, &bottom_up_);
    if (!caption.empty()) mjr_drawPixels(bottom_up_.data(), nullptr, viewport, &context_);
  }
  if (!caption.empty()) {
    const std::string text(caption);
    mjr_overlay(mjFONT_SHADOW, mjGRID_TOPLEFT, viewport, text.c_str(), nullptr, &context_);
  }
  if (!options_.sky || !caption.empty()) {
    mjr_readPixels(bottom_up_.data(), nullptr, viewport, &context_);
  }
  if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
    return absl::InternalError(
        absl::StrCat("OffscreenRenderer::Render: OpenGL error 0x", absl::Hex(err)));
  }

  // OpenGL reads bottom row first
  const size_t row_bytes = static_cast<size_t>(width_) * 3;
  rgb->resize(row_bytes * height_);
  for (int y = 0; y < height_; ++y) {
    std::memcpy(rgb->data() + row_bytes * y, bottom_up_.data() + row_bytes * (height_ - 1 - y),
                row_bytes);
  }
  return absl::OkStatus();
}

absl::Status OffscreenRenderer::RenderBodyIds(const mjData* d, const CameraSpec& cam,
                                              std::vector<int>* body_ids) {
  if (d == nullptr || body_ids == nullptr) {
    return absl::InvalidArgumentError("OffscreenRenderer::RenderBodyIds: data or output is null");
  }
  if (absl::Status s = DrawScene(d, cam, true); !s.ok()) return s;
  const mjrRect viewport = {0, 0, width_, height_};
  mjr_readPixels(bottom_up_.data(), nullptr, viewport, &context_);
  if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
    return absl::InternalError(
        absl::StrCat("OffscreenRenderer::RenderBodyIds: OpenGL error 0x", absl::Hex(err)));
  }
  // MuJoCo paints scene geom i with the colour (i + 1) in little-endian RGB; 0 is no geom
  body_ids->assign(static_cast<size_t>(width_) * height_, -1);
  for (int y = 0; y < height_; ++y) {
    const uint8_t* row = bottom_up_.data() + static_cast<size_t>(width_) * 3 * (height_ - 1 - y);
    for (int x = 0; x < width_; ++x) {
      const uint8_t* px = row + 3 * x;
      const int seg = px[0] + (px[1] << 8) + (px[2] << 16) - 1;
      if (seg < 0 || seg >= scene_.ngeom) continue;
      const mjvGeom& g = scene_.geoms[seg];
      if (g.objtype == mjOBJ_GEOM && g.objid >= 0 && g.objid < model_->ngeom) {
        (*body_ids)[static_cast<size_t>(y) * width_ + x] = model_->geom_bodyid[g.objid];
      }
    }
  }
  return absl::OkStatus();
}

}  // namespace simhuman::render
