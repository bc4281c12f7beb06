// Reading the camera, the view bookmarks and the render settings of a scene file.
#include <climits>
#include <cmath>

#include "io/scene_reader_sections.h"
#include "scene/field_rules.h"

namespace rs {

namespace {
// Its own message: "width 20000 is too large (at most 16384 pixels)".
void readImageSide(EntryReader& r, const char* key, int& out) {
    const ParamDescriptor& d = *findParameter(ParamKind::Render, key);
    int value = out;
    if (!r.integer(key, value, int(d.range.min), INT_MAX)) return;
    if (value > d.range.max) {
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

void readCamera(SceneErrorSink& sink, const Json& json, const std::string& pointer,
                Camera& camera) {
    if (!expectObject(sink, json, pointer)) return;
    EntryReader r(sink, json, pointer);
    const auto invalid = readFields(r, ParamKind::Camera, camera);
    if (noneInvalid(invalid, {"position", "target", "up"}))
        if (auto e = cameraLookError(camera)) sink.atValue(r.pointerTo(e.key), e.message);
    camera.extras = r.finish();
}

void readViews(SceneErrorSink& sink, const Json& json, SceneDocument& doc) {
    if (!expectArray(sink, json, "/views")) return;
    UniqueNames names("view");
    for (std::size_t i = 0; i < json.size(); ++i) {
        const std::string at = appendPointer("/views", i);
        if (!expectObject(sink, json[i], at)) continue;
        EntryReader r(sink, json[i], at);
        ViewBookmark view;
        if (r.name(view.name)) names.add(sink, view.name, at);
        if (const Json* camera = r.get("camera"))
            readCamera(sink, *camera, r.pointerTo("camera"), view.camera);
        else
            r.missing("camera");
        view.extras = r.finish();
        doc.views.push_back(std::move(view));
    }
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
    // The descriptors' upper limits: beyond them a render overflows the stack or never ends.
    readFields(r, ParamKind::Render, settings, {"width", "height"});
    settings.extras = r.finish();
}

}  // namespace rs
