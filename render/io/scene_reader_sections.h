// The per-section readers of a scene file (camera, render, materials, lights, objects).
#pragma once

#include <string>
#include <unordered_map>

#include "io/scene_entry_reader.h"
#include "scene/document.h"

namespace rs {

/// Reads `/camera` into `camera`, checking that it can actually look somewhere.
void readCamera(SceneErrorSink& sink, const Json& json, Camera& camera);
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
