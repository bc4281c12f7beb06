// The per-section readers of a scene file (camera, views, render, materials, lights, objects).
#pragma once

#include <algorithm>
#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "io/scene_entry_reader.h"
#include "scene/document.h"
#include "scene/parameters.h"

namespace rs {

/// Reads the camera object at `pointer` (`/camera`, `/views/N/camera`) into `camera`,
/// checking that it can actually look somewhere.
void readCamera(SceneErrorSink& sink, const Json& json, const std::string& pointer, Camera& camera);
/// Reads `/views`, appending to `doc.views`; names are checked for uniqueness.
void readViews(SceneErrorSink& sink, const Json& json, SceneDocument& doc);
/// Reads `/render` into `settings`.
void readRenderSettings(SceneErrorSink& sink, const Json& json, RenderSettings& settings);
/// Reads `/materials`, appending to `doc.materials`; names are checked for uniqueness.
void readMaterials(SceneErrorSink& sink, const Json& json, SceneDocument& doc);
/// Reads `/lights`, appending to `doc` with fresh ids; names are checked for uniqueness.
void readLights(SceneErrorSink& sink, const Json& json, SceneDocument& doc);
/// Reads `/objects`, appending to `doc` with fresh ids and loading meshes relative to
/// `baseDir`. Materials must already be read: objects refer to them by name.
void readObjects(SceneErrorSink& sink, const Json& json, const std::string& baseDir,
                 SceneDocument& doc);

/// Reads a material's `color` given as an object (`/materials/N/color` at `pointer`): the
/// checker or the image-texture form.
void readColorPattern(SceneErrorSink& sink, const Json& json, const std::string& pointer,
                      ColorPattern& out);
/// Reads `/environment`.
void readEnvironment(SceneErrorSink& sink, const Json& json, Environment& environment);
/// Resolves the image files of `doc` (textures, the environment) against `baseDir` and
/// reports each that cannot be read to `warnings`, naming its key: the scene still loads and
/// shows such an image as the missing-image pattern.
void checkImageFiles(SceneErrorSink& warnings, const std::string& baseDir, SceneDocument& doc);

/// Reads every field the descriptors of `kind` name, except `skip`, into `target`: the
/// descriptors are the format's schema, so a field added there is read here too. Returns
/// the keys that were present but invalid (each already reported).
template <class T>
std::vector<std::string> readFields(EntryReader& r, ParamKind kind, T& target,
                                    std::initializer_list<std::string_view> skip = {}) {
    std::vector<std::string> invalid;
    for (const ParamDescriptor& d : parameters(kind)) {
        if (std::find(skip.begin(), skip.end(), d.key) != skip.end()) continue;
        ParamValue value;
        const EntryReader::Read read = r.parameter(d, value);
        if (read == EntryReader::Read::Invalid) invalid.push_back(d.key);
        if (read != EntryReader::Read::Ok) continue;
        // The reader has checked what the descriptor says; a refusal here is a bug.
        if (std::string e = setField(target, d.key, value); !e.empty())
            r.sink().atValue(r.pointerTo(d.key), e);
    }
    return invalid;
}

/// True when none of `keys` is in `invalid`.
inline bool noneInvalid(const std::vector<std::string>& invalid,
                        std::initializer_list<std::string_view> keys) {
    for (std::string_view k : keys)
        if (std::find(invalid.begin(), invalid.end(), k) != invalid.end()) return false;
    return true;
}

/// Checks that `json` (at `pointer`) is an array; reports and returns false otherwise.
bool expectArray(SceneErrorSink& sink, const Json& json, const std::string& pointer);
/// Checks that `json` (at `pointer`) is an object; reports and returns false otherwise.
bool expectObject(SceneErrorSink& sink, const Json& json, const std::string& pointer);

/// Remembers the names of one list so a repeated name is reported where it repeats.
class UniqueNames {
public:
    explicit UniqueNames(const char* kind) : kind_(kind) {}
    /// Records `name` read at `entryPointer`; reports it if an earlier entry had it.
    void add(SceneErrorSink& sink, const std::string& name, const std::string& entryPointer);

private:
    const char* kind_;
    /// Name -> entry pointer of its first use: a hash map, so 100,000 objects load in linear
    /// time (a list scan made that 38 s).
    std::unordered_map<std::string, std::string> seen_;
};

}  // namespace rs
