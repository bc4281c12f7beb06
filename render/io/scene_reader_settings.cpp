// Reading the camera and render settings of a scene file.
#include <climits>
#include <cmath>

#include "io/scene_reader_sections.h"

namespace rs {

namespace {
glm::dvec3 toDouble(const Vec3& v) {
    return glm::dvec3(v.x, v.y, v.z);
}

void checkCameraCanLook(SceneErrorSink& sink, const Camera& camera) {
    // In double: two distinct floats always differ, however close they are.
    glm::dvec3 dir = toDouble(camera.target) - toDouble(camera.position);
    if (dir == glm::dvec3(0.0)) {
        sink.atValue("/camera/target", "camera target must differ from its position");
        return;
    }
    glm::dvec3 up = toDouble(camera.up);
    double crossLength = glm::length(glm::cross(up, dir));
    if (crossLength <= 1e-6 * glm::length(up) * glm::length(dir))
        sink.atValue("/camera/up", "up must not be parallel to the view direction");
}

void readImageSide(EntryReader& r, const char* key, int& out) {
    int value = out;
    if (!r.integer(key, value, 1, INT_MAX)) return;
    if (value > kMaxImageSide) {
        r.sink().atValue(r.pointerTo(key), std::string(key) + " " + std::to_string(value) +
                                               " is too large (at most " +
                                               std::to_string(kMaxImageSide) + " pixels)");
        return;
    }
    out = value;
}
}  // namespace

bool expectArray(SceneErrorSink& sink, const Json& json, const std::string& pointer) {
    if (json.is_array()) return true;
    sink.atValue(pointer, "must be an array, got " + describeJson(json));
    return false;
}

bool expectObject(SceneErrorSink& sink, const Json& json, const std::string& pointer) {
    if (json.is_object()) return true;
    sink.atValue(pointer, "must be an object, got " + describeJson(json));
    return false;
}

void readCamera(SceneErrorSink& sink, const Json& json, Camera& camera) {
    if (!expectObject(sink, json, "/camera")) return;
    EntryReader r(sink, json, "/camera");
    r.enumeration(
        "projection", camera.projection,
        {{"perspective", Projection::Perspective}, {"orthographic", Projection::Orthographic}});
    bool placed = r.vector("position", camera.position, VectorRule::Any);
    placed = r.vector("target", camera.target, VectorRule::Any) && placed;
    placed = r.vector("up", camera.up, VectorRule::NonZero) && placed;
    r.number("fov_y", camera.fovY, NumberRange::open(0.0, 180.0));
    r.number("ortho_height", camera.orthoHeight, NumberRange::positive());
    if (placed) checkCameraCanLook(sink, camera);
    camera.extras = r.finish();
}

void readRenderSettings(SceneErrorSink& sink, const Json& json, RenderSettings& settings) {
    if (!expectObject(sink, json, "/render")) return;
    EntryReader r(sink, json, "/render");
    // Images beyond kMaxImageSide or kMaxImagePixels would need gigabytes of frame buffer;
    // refuse them at load time instead of failing an allocation deep inside a render.
    readImageSide(r, "width", settings.width);
    readImageSide(r, "height", settings.height);
    if (std::string area = imageSizeError(settings.width, settings.height); !area.empty())
        sink.atValue("/render", area);
    // Upper limits the format leaves open: beyond them a render overflows the stack or never ends.
    r.integer("max_depth", settings.maxDepth, 0, kMaxDepthLimit);
    r.number("min_weight", settings.minWeight, NumberRange::fractionBelowOne());
    r.integer("shadow_samples", settings.shadowSamples, 0, kMaxSampleCount);
    r.integer("supersampling", settings.supersampling, 1, kMaxSampleCount);
    r.boolean("adaptive_supersampling", settings.adaptiveSupersampling);
    r.enumeration("tonemap", settings.tonemap,
                  {{"clamp", ToneMap::Clamp},
                   {"linear", ToneMap::Linear},
                   {"reinhard", ToneMap::Reinhard},
                   {"aces", ToneMap::Aces}});
    r.number("exposure", settings.exposure, NumberRange::any());
    r.vector("background", settings.background, VectorRule::NonNegative);
    r.vector("ambient", settings.ambient, VectorRule::NonNegative);
    settings.extras = r.finish();
}

}  // namespace rs
