// An asset's lights and cameras as ours: each placed by its node's world transform and the
// asset's placement. assimp stores them in their node's space (aiLight::mPosition is (0,0,0)
// for glTF punctual lights, assimp issue 6364), and its importers disagree on angles, so the
// conversions below say which importer they are for.
#include "io/asset_lights.h"

#include <assimp/scene.h>

#include <algorithm>
#include <cmath>

namespace rs {

namespace {
using DMat4 = glm::dmat4;
using DVec3 = glm::dvec3;

constexpr double kPiD = 3.14159265358979323846;

double degrees(double radians) {
    return radians * 180.0 / kPiD;
}

DMat4 toGlm(const aiMatrix4x4& m) {
    // aiMatrix4x4 is row-major (a4, b4, c4 the translation); glm is column-major.
    return DMat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4,
                 m.c4, m.d4);
}

DVec3 toD(const aiVector3D& v) {
    return DVec3(v.x, v.y, v.z);
}

Vec3 toF(const DVec3& v) {
    return Vec3(float(v.x), float(v.y), float(v.z));
}

bool finite(const DVec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

DVec3 point(const DMat4& m, const DVec3& p) {
    return DVec3(m * glm::dvec4(p, 1.0));
}

DVec3 vector(const DMat4& m, const DVec3& v) {
    return DVec3(m * glm::dvec4(v, 0.0));
}

/// The node's transform to the asset's space: its own, then each parent's, up to the root.
/// Lights and cameras are tied to nodes by name (assimp's rule); false when none has it.
bool nodeToAsset(const aiScene& scene, const aiString& name, DMat4& out) {
    const aiNode* node = scene.mRootNode ? scene.mRootNode->FindNode(name) : nullptr;
    if (!node) return false;
    out = DMat4(1.0);
    for (; node; node = node->mParent) out = toGlm(node->mTransformation) * out;
    return true;
}

/// Whether the scene came from one of assimp's glTF importers (1.0 or 2.0), which its
/// "SourceAsset_Format" metadata names ("glTF2 Importer", "glTF Importer").
bool fromGltf(const aiScene& scene) {
    aiString format;
    if (!scene.mMetaData || !scene.mMetaData->Get("SourceAsset_Format", format)) return false;
    return std::string(format.C_Str()).find("glTF") != std::string::npos;
}

std::string quoted(const aiString& name) {
    std::string text(1, '\'');  // appended, not operator+: GCC 12's -Wrestrict misfires on it
    text.append(name.C_Str(), name.length).push_back('\'');
    return text;
}

const char* typeName(aiLightSourceType type) {
    switch (type) {
        case aiLightSource_AMBIENT:
            return "an ambient light";
        case aiLightSource_AREA:
            return "an area light";
        case aiLightSource_UNDEFINED:
            return "a light of no known type";
        default:
            return "a light of a type RayStudio does not have";
    }
}

void addLight(const aiScene& scene, const aiLight& in, const DMat4& assetToScene, bool gltf,
              AssetLightsAndCameras& out) {
    const std::string who = "light " + quoted(in.mName);
    if (in.mType != aiLightSource_POINT && in.mType != aiLightSource_SPOT &&
        in.mType != aiLightSource_DIRECTIONAL) {
        out.notes.push_back(who + " is " + typeName(in.mType) + ": skipped");
        return;
    }
    DMat4 toScene = assetToScene;
    if (DMat4 node; nodeToAsset(scene, in.mName, node)) {
        toScene = assetToScene * node;
    } else {
        out.notes.push_back(who + " has no node of its name: placed by its own position alone");
    }

    Light light;
    light.name = in.mName.C_Str();
    // assimp folds the intensity into the colour (glTF: color * intensity; FBX: color *
    // Intensity / 100); ours is a colour in [0, 1] times an intensity.
    const DVec3 power(in.mColorDiffuse.r, in.mColorDiffuse.g, in.mColorDiffuse.b);
    const double brightest = std::max({power.x, power.y, power.z});
    if (!finite(power) || !(brightest > 0.0) || std::min({power.x, power.y, power.z}) < 0.0) {
        out.notes.push_back(
            who + " has no usable colour (black, negative or not a number): " + "skipped");
        return;
    }
    light.color = toF(power / brightest);
    light.intensity = float(brightest);

    const DVec3 position = point(toScene, toD(in.mPosition));
    const DVec3 direction = vector(toScene, toD(in.mDirection));
    if (in.mType == aiLightSource_DIRECTIONAL) {
        light.type = LightType::Directional;
        if (!finite(direction) || glm::length(direction) == 0.0) {
            out.notes.push_back(who + " is a directional light without a direction: skipped");
            return;
        }
        light.direction = toF(glm::normalize(direction));
    } else {
        light.type = in.mType == aiLightSource_SPOT ? LightType::Spot : LightType::Point;
        if (!finite(position)) {
            out.notes.push_back(who + " has no finite position: skipped");
            return;
        }
        light.position = toF(position);
        if (in.mAttenuationLinear != 0.0f || in.mAttenuationQuadratic != 0.0f)
            out.notes.push_back(who + ": its fall-off with distance is dropped (RayStudio's " +
                                "lights do not fade with distance)");
    }
    if (light.type == LightType::Spot) {
        const DVec3 target = position + direction;
        if (!finite(direction) || glm::length(direction) == 0.0 || toF(target) == light.position) {
            out.notes.push_back(who + " is a spot light without a direction: skipped");
            return;
        }
        light.target = toF(target);
        // assimp documents full cone angles and its FBX, Collada and Blender importers store
        // them; its glTF importer copies glTF's half-angles (inner/outerConeAngle) unchanged.
        const double half = gltf ? 1.0 : 0.5;
        auto halfAngle = [&](float angle) {
            return float(std::clamp(degrees(double(angle) * half), 0.0, 90.0));
        };
        light.coneRadius = halfAngle(in.mAngleInnerCone);
        light.coneFalloff = halfAngle(in.mAngleOuterCone);
    }
    out.lights.push_back(std::move(light));
}

void addCamera(const aiScene& scene, const aiCamera& in, const DMat4& assetToScene, bool gltf,
               AssetLightsAndCameras& out) {
    const std::string who = "camera " + quoted(in.mName);
    DMat4 toScene = assetToScene;
    if (DMat4 node; nodeToAsset(scene, in.mName, node)) {
        toScene = assetToScene * node;
    } else {
        out.notes.push_back(who + " has no node of its name: placed by its own position alone");
    }
    // glTF cameras sit at their node's origin, but assimp 5.2.5's glTF importer also copies the
    // node's translation into mPosition, which the node's transform would then add twice.
    const DVec3 local = gltf ? DVec3(0.0) : toD(in.mPosition);
    const DVec3 position = point(toScene, local);
    const DVec3 look = vector(toScene, toD(in.mLookAt));
    const DVec3 up = vector(toScene, toD(in.mUp));
    if (!finite(position) || !finite(look) || !finite(up) || glm::length(look) == 0.0 ||
        glm::length(glm::cross(look, up)) == 0.0) {
        out.notes.push_back(who + " has no usable position, direction or up: skipped");
        return;
    }

    AssetCamera camera;
    camera.name = in.mName.C_Str();
    Camera& c = camera.camera;
    c.position = toF(position);
    // One asset unit ahead (after the placement): where the asset puts it when it says.
    c.target = toF(position + look / glm::length(toD(in.mLookAt)));
    c.up = toF(glm::normalize(up));
    if (c.target == c.position) {
        out.notes.push_back(who + " looks nowhere at this scale: skipped");
        return;
    }
    const double aspect = in.mAspect;
    if (in.mOrthographicWidth > 0.0f) {
        // mOrthographicWidth is half the visible width (glTF's xmag); the height follows from
        // the aspect, and the placement scales it as it scales the camera's up.
        c.projection = Projection::Orthographic;
        const double scale = glm::length(up) / glm::length(toD(in.mUp));
        c.orthoHeight = float(2.0 * in.mOrthographicWidth / (aspect > 0.0 ? aspect : 1.0) * scale);
    } else {
        c.projection = Projection::Perspective;
        const double stored = in.mHorizontalFOV;
        double fovY = 0.0;
        if (gltf) {
            // assimp 5.2.5 stores yfov * aspect (yfov alone when the aspect is absent).
            fovY = stored / (aspect > 0.0 ? aspect : 1.0);
        } else {
            // Its FBX, Collada and Blender importers store the full horizontal angle (the
            // header's "half" notwithstanding): the vertical one follows from the aspect.
            if (!(aspect > 0.0))
                out.notes.push_back(who + " has no aspect ratio: its field of view is taken " +
                                    "as vertical");
            fovY = 2.0 * std::atan(std::tan(stored / 2.0) / (aspect > 0.0 ? aspect : 1.0));
        }
        fovY = degrees(fovY);
        if (!(fovY > 0.0 && fovY < 180.0)) {
            out.notes.push_back(who + " has no usable field of view: " +
                                std::to_string(int(Camera{}.fovY)) + " degrees used");
            fovY = Camera{}.fovY;
        }
        c.fovY = float(fovY);
    }
    out.cameras.push_back(std::move(camera));
}
}  // namespace

AssetLightsAndCameras assetLightsAndCameras(const aiScene& scene, const Mat4& assetToScene) {
    AssetLightsAndCameras out;
    const DMat4 toScene(assetToScene);
    const bool gltf = fromGltf(scene);
    for (unsigned i = 0; i < scene.mNumLights; ++i)
        if (scene.mLights[i]) addLight(scene, *scene.mLights[i], toScene, gltf, out);
    for (unsigned i = 0; i < scene.mNumCameras; ++i)
        if (scene.mCameras[i]) addCamera(scene, *scene.mCameras[i], toScene, gltf, out);
    return out;
}

}  // namespace rs
