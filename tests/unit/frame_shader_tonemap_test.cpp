// The viewport's shader (resources/shaders/frame.frag) tone maps and sRGB-encodes on the GPU
// what render/image/tonemap.cpp does for image files and the CPU display path: the same
// operators with the same constants. This test reads the shader's formulas (their shape and
// every constant in them), evaluates them as written on sample radiances, and compares with
// toneMap and srgbEncode: it fails when either side changes alone.

// GCC 12 at -O2 with ASan warns that std::regex's own NFA states "may be used uninitialized"
// (a known false positive inside libstdc++'s <regex>), which -Werror turns into an error.
// The pragma must come before the first include: the warning is placed in those headers.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "image/tonemap.h"

namespace rs {
namespace {

std::string shaderText() {
    std::ifstream in(RAYSTUDIO_SCENES_DIR "/../resources/shaders/frame.frag");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The numbers that `pattern` (with a group per number) finds in `text`, or none (a failure
/// is recorded) when the shader no longer reads that way.
std::vector<float> numbers(const std::string& text, const std::string& pattern, const char* what) {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex(pattern))) {
        ADD_FAILURE() << "frame.frag's " << what << " no longer reads as this test expects ("
                      << pattern << "): compare it with render/image/tonemap.cpp and update both";
        return {};
    }
    std::vector<float> out;
    for (std::size_t i = 1; i < m.size(); ++i)
        out.push_back(std::strtof(m.str(i).c_str(), nullptr));
    return out;
}

const std::string kNumber = R"(([0-9]+\.[0-9]*(?:[eE][-+]?[0-9]+)?))";
const std::string kSpace = R"(\s*)";

/// frame.frag's tone map and sRGB step, with the constants read from it, written as it
/// computes them (exposure's gain exp2(exposure); sanitize; the operator; clamp).
struct ShaderToneMap {
    float largest = 0.0f;            ///< sanitize's cap
    float linearWhite = 0.0f;        ///< TONEMAP_LINEAR's divisor
    std::vector<float> lumaWeights;  ///< TONEMAP_REINHARD's dot
    std::vector<float> aces;         ///< a, b, c, d, e of x(ax+b) / (x(cx+d)+e)
    std::vector<float> srgb;         ///< threshold, toe slope, scale, gamma, offset
    bool complete = false;

    explicit ShaderToneMap(const std::string& text) {
        const std::string s = kSpace;
        const auto one = [&](const std::string& pattern, const char* what) {
            const std::vector<float> v = numbers(text, pattern, what);
            return v.empty() ? 0.0f : v[0];
        };
        largest = one(R"(float sanitize\(float x\) \{ return x > 0\.0 \? min\(x, )" + kNumber +
                          R"(\) : 0\.0; \})",
                      "sanitize");
        linearWhite = one(R"(TONEMAP_LINEAR\) return clamp\(x / )" + kNumber + R"(, 0\.0, 1\.0\);)",
                          "Linear operator");
        lumaWeights =
            numbers(text,
                    R"(float lum = dot\(x, vec3\()" + kNumber + ", " + kNumber + ", " + kNumber +
                        R"(\)\);)" + s + R"(if \(lum <= 0\.0\) return vec3\(0\.0\);)" + s +
                        R"(return clamp\(x \* \(\(lum / \(1\.0 \+ lum\)\) / lum\), 0\.0, 1\.0\);)",
                    "Reinhard operator");
        aces = numbers(text,
                       R"(return clamp\(\(x \* \()" + kNumber + R"( \* x \+ )" + kNumber +
                           R"(\)\) / \(x \* \()" + kNumber + R"( \* x \+ )" + kNumber +
                           R"(\) \+ )" + kNumber + R"(\), 0\.0, 1\.0\);)",
                       "ACES operator");
        srgb = numbers(text,
                       R"(c = clamp\(c, 0\.0, 1\.0\);)" + s + R"(return c <= )" + kNumber +
                           R"( \? )" + kNumber + R"( \* c : )" + kNumber +
                           R"( \* pow\(c, 1\.0 / )" + kNumber + R"(\) - )" + kNumber + ";",
                       "sRGB step");
        // The frame around them: the gain, the sanitized channels, the operators' order and
        // the clamp every other operator (Clamp) falls to.
        numbers(text, R"(float gain = exp2\(exposure\);)", "exposure gain");
        numbers(text,
                R"(vec3 x = vec3\(sanitize\(hdr\.r \* gain\), sanitize\(hdr\.g \* gain\), )"
                R"(sanitize\(hdr\.b \* gain\)\);)",
                "sanitized input");
        numbers(text,
                R"(TONEMAP_ACES\) return vec3\(aces\(x\.r\), aces\(x\.g\), aces\(x\.b\)\);)" + s +
                    R"(return clamp\(x, 0\.0, 1\.0\);)",
                "Clamp operator");
        complete = largest > 0.0f && linearWhite > 0.0f && lumaWeights.size() == 3 &&
                   aces.size() == 5 && srgb.size() == 5;
    }

    float sanitize(float x) const { return x > 0.0f ? std::min(x, largest) : 0.0f; }
    static float clamp01(float x) { return std::clamp(x, 0.0f, 1.0f); }
    float acesCurve(float x) const {
        return clamp01((x * (aces[0] * x + aces[1])) / (x * (aces[2] * x + aces[3]) + aces[4]));
    }
    Color toneMap(const Color& hdr, ToneMap op, float exposure) const {
        const float gain = std::exp2(exposure);
        const Color x(sanitize(hdr.x * gain), sanitize(hdr.y * gain), sanitize(hdr.z * gain));
        switch (op) {
            case ToneMap::Linear:
                return Color(clamp01(x.x / linearWhite), clamp01(x.y / linearWhite),
                             clamp01(x.z / linearWhite));
            case ToneMap::Reinhard: {
                const float lum =
                    lumaWeights[0] * x.x + lumaWeights[1] * x.y + lumaWeights[2] * x.z;
                if (lum <= 0.0f) return Color(0.0f);
                const float scale = (lum / (1.0f + lum)) / lum;
                return Color(clamp01(x.x * scale), clamp01(x.y * scale), clamp01(x.z * scale));
            }
            case ToneMap::Aces:
                return Color(acesCurve(x.x), acesCurve(x.y), acesCurve(x.z));
            case ToneMap::Clamp:
                break;
        }
        return Color(clamp01(x.x), clamp01(x.y), clamp01(x.z));
    }
    float srgbEncode(float c) const {
        c = clamp01(c);
        return c <= srgb[0] ? srgb[1] * c : srgb[2] * std::pow(c, 1.0f / srgb[3]) - srgb[4];
    }
};

TEST(FrameShaderToneMap, ShaderReadsAsTheTestExpects) {
    ASSERT_FALSE(shaderText().empty()) << "resources/shaders/frame.frag not found";
    EXPECT_TRUE(ShaderToneMap(shaderText()).complete);
}

TEST(FrameShaderToneMap, EveryOperator_MapsAsTheCpuToneMap) {
    const ShaderToneMap shader(shaderText());
    ASSERT_TRUE(shader.complete);
    const float values[] = {0.0f, -1.0f, 1e-4f, 0.01f, 0.18f, 0.5f,    0.9f,
                            1.0f, 1.7f,  3.0f,  4.0f,  12.0f, 9000.0f, 1e5f};
    const Color colors[] = {Color(1.0f, 1.0f, 1.0f), Color(1.0f, 0.2f, 0.05f),
                            Color(0.1f, 0.6f, 2.0f), Color(0.0f, 0.0f, 1.0f)};
    for (ToneMap op : {ToneMap::Clamp, ToneMap::Linear, ToneMap::Reinhard, ToneMap::Aces}) {
        for (float exposure : {-2.0f, 0.0f, 1.5f}) {
            for (float v : values) {
                for (const Color& tint : colors) {
                    const Color hdr = v * tint;
                    const Color cpu = toneMap(hdr, op, exposure);
                    const Color gpu = shader.toneMap(hdr, op, exposure);
                    for (int k = 0; k < 3; ++k)
                        EXPECT_NEAR(gpu[k], cpu[k], 1e-6f)
                            << "operator " << int(op) << ", exposure " << exposure << ", radiance "
                            << hdr[k] << " (channel " << k << ")";
                }
            }
        }
    }
}

TEST(FrameShaderToneMap, SrgbStep_EncodesAsTheCpu) {
    const ShaderToneMap shader(shaderText());
    ASSERT_TRUE(shader.complete);
    for (int i = 0; i <= 1000; ++i) {
        const float d = float(i) / 1000.0f;
        EXPECT_NEAR(shader.srgbEncode(d), srgbEncode(d), 1e-6f) << "display value " << d;
    }
    // Around the toe's end, where the two pieces meet.
    for (float d : {0.0031307f, 0.0031308f, 0.0031309f})
        EXPECT_NEAR(shader.srgbEncode(d), srgbEncode(d), 1e-6f) << "display value " << d;
}

}  // namespace
}  // namespace rs
