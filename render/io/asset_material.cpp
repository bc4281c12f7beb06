// The mapping from an assimp material to a RayStudio Material (the table is in the header).
#include "io/asset_material.h"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace rs {

namespace {

std::string number(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

std::string describe(const Color& c) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", double(c.x), double(c.y), double(c.z));
    return text;
}

/// Reads one number; false when absent, and when not finite (then noted).
bool readNumber(const aiMaterial& in, const char* key, unsigned type, unsigned index,
                const char* what, std::vector<std::string>& notes, float& out) {
    ai_real value = 0;
    if (in.Get(key, type, index, value) != aiReturn_SUCCESS) return false;
    if (!std::isfinite(value)) {
        notes.push_back(std::string(what) + " is not a finite number; ignored");
        return false;
    }
    out = float(value);
    return true;
}

/// Reads an RGB colour (the alpha of an RGBA one is read separately); false when absent, and
/// when a component is not finite (then noted). Negative components become 0.
bool readColor(const aiMaterial& in, const char* key, unsigned type, unsigned index,
               const char* what, std::vector<std::string>& notes, Color& out) {
    aiColor3D value;
    if (in.Get(key, type, index, value) != aiReturn_SUCCESS) return false;
    if (!std::isfinite(value.r) || !std::isfinite(value.g) || !std::isfinite(value.b)) {
        notes.push_back(std::string(what) + " is not a finite colour; ignored");
        return false;
    }
    out = Color(std::max(0.0f, float(value.r)), std::max(0.0f, float(value.g)),
                std::max(0.0f, float(value.b)));
    return true;
}

float clamp01(float v) {
    return std::clamp(v, 0.0f, 1.0f);
}

std::string shortName(const std::string& path) {
    const std::size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// Index N of "*N" (digits only), or -1.
int starIndex(const std::string& path) {
    if (path.size() < 2 || path[0] != '*' || path.size() > 10) return -1;
    int n = 0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        if (path[i] < '0' || path[i] > '9') return -1;
        n = n * 10 + (path[i] - '0');
    }
    return n;
}

std::string resolveAgainst(const std::string& file, const std::string& dir) {
    namespace fs = std::filesystem;
    fs::path path(file);
    if (path.is_relative() && !dir.empty()) path = fs::path(dir) / path;
    return path.lexically_normal().string();
}

const char* wrapName(int mode) {
    switch (mode) {
        case aiTextureMapMode_Clamp:
            return "clamps";
        case aiTextureMapMode_Mirror:
            return "mirrors";
        case aiTextureMapMode_Decal:
            return "decals";
        default:
            return "wraps oddly";
    }
}

/// Where texture `t` (its path read) comes from: an embedded image (by "*N" or by a name an
/// embedded image carries) or a file beside the asset. False when it names an embedded image
/// the asset lacks (noted; the texture is then dropped).
bool locateTexture(const AssetTextureContext& context, const char* kind, AssetTexture& t,
                   std::vector<std::string>& notes) {
    const int star = starIndex(t.path);
    if (!t.path.empty() && t.path[0] == '*') {
        if (star < 0 || std::size_t(star) >= context.embeddedNames.size()) {
            notes.push_back("its " + std::string(kind) + " texture names embedded image " + t.path +
                            ", but the asset holds " +
                            std::to_string(context.embeddedNames.size()) + "; left untextured");
            return false;
        }
        t.source = AssetTexture::Source::Embedded;
        t.embeddedIndex = star;
        return true;
    }
    // An embedded image may carry the name the material uses (FBX does that).
    const std::string name = shortName(t.path);
    for (std::size_t i = 0; i < context.embeddedNames.size(); ++i)
        if (!context.embeddedNames[i].empty() && shortName(context.embeddedNames[i]) == name) {
            t.source = AssetTexture::Source::Embedded;
            t.embeddedIndex = int(i);
            break;
        }
    if (t.source == AssetTexture::Source::None) {
        t.source = AssetTexture::Source::File;
        std::string slashed = t.path;
        std::replace(slashed.begin(), slashed.end(), '\\', '/');
        t.look.image.file = slashed;
        t.look.image.resolvedPath = resolveAgainst(slashed, context.assetDir);
    }
    return true;
}

/// The texture's UV channel and wrap modes, noted where RayStudio reads them otherwise.
void readTextureMapping(const aiMaterial& in, aiTextureType type, AssetTexture& t,
                        std::vector<std::string>& notes) {
    int channel = 0;
    if (in.Get(AI_MATKEY_UVWSRC(type, 0), channel) == aiReturn_SUCCESS && channel > 0) {
        t.uvChannel = unsigned(channel);
        notes.push_back("its texture reads UV channel " + std::to_string(channel) +
                        "; the mesh carries channel 0 only");
    }
    for (const auto& [key, axis] : {std::pair{_AI_MATKEY_MAPPINGMODE_U_BASE, "u"},
                                    std::pair{_AI_MATKEY_MAPPINGMODE_V_BASE, "v"}}) {
        int mode = aiTextureMapMode_Wrap;
        if (in.Get(key, type, 0, mode) == aiReturn_SUCCESS && mode != aiTextureMapMode_Wrap)
            notes.push_back(std::string("its texture ") + wrapName(mode) + " in " + axis +
                            "; RayStudio repeats it");
    }
}

/// The texture's UV transform: its scale and offset kept, a rotation or a zero scale noted
/// and left out.
void readTextureTransform(const aiMaterial& in, aiTextureType type, AssetTexture& t,
                          std::vector<std::string>& notes) {
    aiUVTransform uv;
    if (in.Get(AI_MATKEY_UVTRANSFORM(type, 0), uv) != aiReturn_SUCCESS) return;
    const float values[] = {float(uv.mTranslation.x), float(uv.mTranslation.y),
                            float(uv.mScaling.x), float(uv.mScaling.y), float(uv.mRotation)};
    if (!std::all_of(std::begin(values), std::end(values),
                     [](float v) { return std::isfinite(v); })) {
        notes.push_back("its texture transform is not finite; ignored");
        return;
    }
    t.hasTransform = true;
    t.transform = {values[0], values[1], values[2], values[3], values[4]};
    if (values[4] != 0.0f) {
        notes.push_back("its texture transform rotates by " + number(values[4]) +
                        " rad, which a texture cannot; the transform is left out");
    } else if (values[2] == 0.0f || values[3] == 0.0f) {
        notes.push_back("its texture transform scales by 0; the transform is left out");
    } else {
        t.look.scaleU = values[2], t.look.scaleV = values[3];
        t.look.offsetU = values[0], t.look.offsetV = values[1];
    }
}

void readTexture(const aiMaterial& in, const AssetTextureContext& context, AssetMaterial& out) {
    aiTextureType type = aiTextureType_BASE_COLOR;
    if (in.GetTextureCount(type) == 0) type = aiTextureType_DIFFUSE;
    const unsigned count = in.GetTextureCount(type);
    if (count == 0) return;
    const char* kind = type == aiTextureType_BASE_COLOR ? "base colour" : "diffuse";
    auto& notes = out.notes;
    if (count > 1)
        notes.push_back(std::string("only the first of its ") + std::to_string(count) + " " + kind +
                        " textures is used");
    aiString file;
    if (in.Get(AI_MATKEY_TEXTURE(type, 0), file) != aiReturn_SUCCESS || file.length == 0) return;
    AssetTexture& t = out.texture;
    t.path = file.C_Str();
    if (!locateTexture(context, kind, t, notes)) {
        t = AssetTexture{};
        return;
    }
    readTextureMapping(in, type, t, notes);
    readTextureTransform(in, type, t, notes);
    if (t.source == AssetTexture::Source::File) out.material.pattern = t.look;
}

/// A metal/roughness material's metallic and roughness as reflectivity, specular and
/// shininess; false when the asset gives no metallic factor (a Phong material).
bool readMetalRoughness(const aiMaterial& in, Material& m, std::vector<std::string>& notes,
                        float& metallic) {
    float roughness = 1.0f;
    // A metallic factor marks a metal/roughness material (glTF writes both factors). A
    // roughness alone does not: assimp 5.2.5's FBX reader derives one from the Phong
    // exponent (1 - sqrt(shininess) / 10) for every material, PBR or not.
    if (!readNumber(in, AI_MATKEY_METALLIC_FACTOR, "metallic", notes, metallic)) return false;
    readNumber(in, AI_MATKEY_ROUGHNESS_FACTOR, "roughness", notes, roughness);
    metallic = clamp01(metallic);
    roughness = clamp01(roughness);
    m.reflectivity = metallic * (1.0f - roughness);
    m.specular = 1.0f - roughness;
    const float r4 = roughness * roughness * roughness * roughness;
    m.shininess = r4 > 0.0f ? std::clamp(0.5f / r4 - 0.5f, 1.0f, 10000.0f) : 10000.0f;
    // A matte dielectric (m 0, r 1) loses nothing; anything else is an approximation.
    if (metallic > 0.0f || roughness < 1.0f)
        notes.push_back("metallic " + number(metallic) + " and roughness " + number(roughness) +
                        " became reflectivity " + number(m.reflectivity) +
                        " (an untinted mirror), specular " + number(m.specular) +
                        " and shininess " + number(m.shininess));
    return true;
}

/// A Phong material's specular colour (as a white highlight's weight), shininess and
/// reflectivity.
void readPhong(const aiMaterial& in, Material& m, std::vector<std::string>& notes) {
    Color ks(0.0f);
    if (readColor(in, AI_MATKEY_COLOR_SPECULAR, "specular colour", notes, ks)) {
        float weight = luminance(ks);
        float strength = 1.0f;
        if (readNumber(in, AI_MATKEY_SHININESS_STRENGTH, "specular strength", notes, strength))
            weight *= strength;
        m.specular = clamp01(weight);
        if (ks.x != ks.y || ks.y != ks.z)
            notes.push_back("specular colour " + describe(ks) +
                            " became a white highlight of weight " + number(m.specular));
    }
    float shininess = 0.0f;
    if (readNumber(in, AI_MATKEY_SHININESS, "shininess", notes, shininess))
        m.shininess = std::clamp(shininess, 0.0f, 10000.0f);
    float reflectivity = 0.0f;
    if (readNumber(in, AI_MATKEY_REFLECTIVITY, "reflectivity", notes, reflectivity))
        m.reflectivity = clamp01(reflectivity);
}

/// How much light passes the material: its transmission (none for metal) and its see-through
/// alpha (opacity or transparency factor, only where glTF blends).
struct SeeThrough {
    float transmission = 0.0f, alpha = 0.0f;
};
SeeThrough readSeeThrough(const aiMaterial& in, float metallic, std::vector<std::string>& notes) {
    SeeThrough s;
    if (readNumber(in, AI_MATKEY_TRANSMISSION_FACTOR, "transmission", notes, s.transmission))
        s.transmission = clamp01(s.transmission) * (1.0f - metallic);
    float opacity = 1.0f, transparencyFactor = 0.0f;
    if (!readNumber(in, AI_MATKEY_OPACITY, "opacity", notes, opacity) &&
        readNumber(in, AI_MATKEY_TRANSPARENCYFACTOR, "transparency factor", notes,
                   transparencyFactor))
        opacity = 1.0f - transparencyFactor;
    aiString alphaMode;
    if (in.Get(AI_MATKEY_GLTF_ALPHAMODE, alphaMode) == aiReturn_SUCCESS &&
        std::string(alphaMode.C_Str()) != "BLEND") {
        if (std::string(alphaMode.C_Str()) == "MASK")
            notes.push_back("its alpha cut-out (glTF alphaMode MASK) is not rendered");
        opacity = 1.0f;  // glTF alpha is coverage only when blending.
    }
    s.alpha = 1.0f - clamp01(opacity);
    return s;
}

/// The index of refraction: the asset's when positive, else 1 for light let straight through
/// by alpha alone, else glass's 1.5.
float readIor(const aiMaterial& in, const SeeThrough& s, std::vector<std::string>& notes) {
    float ior = 0.0f;
    bool hasIor = readNumber(in, AI_MATKEY_REFRACTI, "ior", notes, ior);
    if (hasIor && ior <= 0.0f) {
        notes.push_back("ior " + number(ior) + " is not positive; ignored");
        hasIor = false;
    }
    if (hasIor) return ior;
    if (s.transmission == 0.0f && s.alpha > 0.0f)
        return 1.0f;  // Alpha lets light straight through.
    return 1.5f;
}

/// An emissive colour noted: the material cannot glow.
void noteEmissive(const aiMaterial& in, std::vector<std::string>& notes) {
    Color emissive(0.0f);
    if (readColor(in, AI_MATKEY_COLOR_EMISSIVE, "emissive colour", notes, emissive) &&
        (emissive.x > 0.0f || emissive.y > 0.0f || emissive.z > 0.0f))
        notes.push_back("emissive colour " + describe(emissive) + " is not rendered");
}

}  // namespace

AssetMaterial mapAssetMaterial(const aiMaterial& in, const AssetTextureContext& context) {
    AssetMaterial out;
    Material& m = out.material;
    auto& notes = out.notes;

    aiString name;
    if (in.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS && name.length > 0)
        m.name = name.C_Str();
    else
        m.name = "asset material " + std::to_string(context.materialIndex);

    const bool hasColor = readColor(in, AI_MATKEY_BASE_COLOR, "base colour", notes, m.color) ||
                          readColor(in, AI_MATKEY_COLOR_DIFFUSE, "diffuse colour", notes, m.color);

    float metallic = 0.0f;
    if (!readMetalRoughness(in, m, notes, metallic)) {
        metallic = 0.0f;
        readPhong(in, m, notes);
    }
    const SeeThrough seeThrough = readSeeThrough(in, metallic, notes);
    m.transparency = std::max(seeThrough.transmission, seeThrough.alpha);
    m.ior = readIor(in, seeThrough, notes);
    if (m.reflectivity + m.transparency > 1.0f) {
        const float was = m.transparency;
        m.transparency = 1.0f - m.reflectivity;
        notes.push_back("transparency " + number(was) + " became " + number(m.transparency) +
                        " to leave room for reflectivity " + number(m.reflectivity));
    }
    noteEmissive(in, notes);
    readTexture(in, context, out);
    // Only a colour the asset gives multiplies its texture; our default grey does not.
    if (hasColor && out.texture.source != AssetTexture::Source::None &&
        (std::abs(m.color.x - 1.0f) > 1e-3f || std::abs(m.color.y - 1.0f) > 1e-3f ||
         std::abs(m.color.z - 1.0f) > 1e-3f))
        notes.push_back("colour " + describe(m.color) +
                        " multiplies the texture in the asset; the texture shows alone");
    return out;
}

}  // namespace rs
