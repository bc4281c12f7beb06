// A fingerprint of everything that decides a render's pixels: the scene, its render settings,
// the meshes' triangles and the ray engine. Parts of one image carry it so a merge can refuse
// parts of another scene or of other settings.
#pragma once

#include <string>

#include "accel/ray_engine.h"
#include "scene/document.h"

namespace rs {

/// 16 hex digits (64-bit FNV-1a) over the serialised document, every mesh's vertices, normals
/// and indices, and the engine's name. Equal documents (ids aside) give equal fingerprints.
std::string renderFingerprint(const SceneDocument& doc, EngineKind engine);

}  // namespace rs
