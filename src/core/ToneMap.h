// Exposure and tone mapping: how linear radiance becomes the display-referred values a PNG
// or the viewer's window shows. The image is multiplied by an exposure, passed through a tone
// curve, then sRGB-encoded (core/ImageIO.h). Exposure 1 with no curve is the linear mapping
// every test and the bench read (DESIGN.md); HDR files never carry either.
//
// Manual exposure: exposure = 2^EV.
// Auto exposure (Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images"):
//     logavg   = exp( mean of ln Y over the pixels showing geometry with Y > kMinLuminance )
//     exposure = kAutoExposureKey / logavg,   kAutoExposureKey = 0.18 (middle grey)
// with Y the Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B. Black pixels (a shadow
// without indirect light) are left out: they say nothing of how bright the lit scene is, and
// a floor in their place would drag the geometric mean down and over-expose the frame.
// The filmic curve is Narkowicz's 2015 fit of ACES (constants in shaders/common/shared.h,
// shared with shaders/common/tonemap.glsl, which the viewer's present pass runs).
#pragma once

#include "core/Image.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gi::core {

enum class ToneCurve { None, Filmic };

inline constexpr float kAutoExposureKey = 0.18f;
inline constexpr float kMinLuminance = 1e-6f;     // W/(m^2 sr): darker counts as black
inline constexpr float kMaxExposureEv = 20.0f;    // |EV| of --exposure and auto exposure

// How to show an image: a fixed EV or the auto exposure, and a curve.
struct ToneMapping {
    bool autoExposure = false;
    float ev = 0.0f;                  // manual exposure, stops (ignored when autoExposure)
    ToneCurve curve = ToneCurve::None;
};

[[nodiscard]] float luminance(const glm::vec3& rgb);
// Narkowicz's ACES fit per channel: 0 -> 0, monotonic, saturates at 1.
[[nodiscard]] float filmicCurve(float x);
[[nodiscard]] glm::vec3 toneCurve(const glm::vec3& exposed, ToneCurve curve);

// exp(mean ln Y) over the pixels whose coverage is above 0.5 (empty coverage: every pixel)
// and whose Y is above kMinLuminance; nullopt when no pixel counts.
[[nodiscard]] std::optional<float> logAverageLuminance(const Image& image,
        const std::vector<float>& coverage);
// kAutoExposureKey / logAverage, kept within 2^+-kMaxExposureEv.
[[nodiscard]] float autoExposure(float logAverage);
// The exposure `mapping` gives `image` (coverage as for logAverageLuminance).
[[nodiscard]] float exposureFor(const ToneMapping& mapping, const Image& image,
        const std::vector<float>& coverage);

// Every pixel times `exposure`, through `curve`: the values writePng then encodes.
[[nodiscard]] Image applyToneMapping(const Image& image, float exposure, ToneCurve curve);

// "none" / "filmic".
[[nodiscard]] std::optional<ToneCurve> parseToneCurve(const std::string& name);
[[nodiscard]] const char* toneCurveName(ToneCurve curve);

} // namespace gi::core
