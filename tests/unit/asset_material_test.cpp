// The mapping from assimp materials to ours, rule by rule (io/asset_material.h), on materials
// built here (asset_material_import_test.cpp has assets read through assimp).
#include "io/asset_material.h"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace rs {
namespace {

constexpr float kTol = 1e-5f;

void addNumber(aiMaterial& m, float v, const char* key, unsigned type, unsigned index) {
    m.AddProperty(&v, 1, key, type, index);
}
void addColor(aiMaterial& m, float r, float g, float b, const char* key, unsigned type,
              unsigned index) {
    aiColor3D c(r, g, b);
    m.AddProperty(&c, 1, key, type, index);
}
void addString(aiMaterial& m, const char* text, const char* key, unsigned type, unsigned index) {
    aiString s(text);
    m.AddProperty(&s, key, type, index);
}

bool hasNote(const AssetMaterial& a, const std::string& part) {
    for (const auto& n : a.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

std::string allNotes(const AssetMaterial& a) {
    std::string all;
    for (const auto& n : a.notes) all += n + "\n";
    return all;
}

void expectColor(const Color& c, float r, float g, float b) {
    EXPECT_NEAR(c.x, r, kTol);
    EXPECT_NEAR(c.y, g, kTol);
    EXPECT_NEAR(c.z, b, kTol);
}

TEST(AssetMaterial, NameComesFromTheAssetOrFromItsIndex) {
    aiMaterial named;
    addString(named, "Brass", AI_MATKEY_NAME);
    EXPECT_EQ(mapAssetMaterial(named, {}).material.name, "Brass");
    aiMaterial nameless;
    AssetTextureContext context;
    context.materialIndex = 7;
    EXPECT_EQ(mapAssetMaterial(nameless, context).material.name, "asset material 7");
}

TEST(AssetMaterial, NothingSetGivesTheDefaultMaterialWithoutNotes) {
    aiMaterial empty;
    const AssetMaterial a = mapAssetMaterial(empty, {});
    Material expected;
    expected.name = "asset material 0";
    EXPECT_EQ(a.material, expected);
    EXPECT_TRUE(a.notes.empty()) << allNotes(a);
    EXPECT_EQ(a.texture.source, AssetTexture::Source::None);
}

TEST(AssetMaterial, BaseColourWinsOverDiffuse) {
    aiMaterial m;
    aiColor4D base(0.2f, 0.4f, 0.6f, 1.0f);
    m.AddProperty(&base, 1, AI_MATKEY_BASE_COLOR);
    addColor(m, 0.9f, 0.9f, 0.9f, AI_MATKEY_COLOR_DIFFUSE);
    expectColor(mapAssetMaterial(m, {}).material.color, 0.2f, 0.4f, 0.6f);
}

TEST(AssetMaterial, DiffuseColourWithoutBaseColour) {
    aiMaterial m;
    addColor(m, 0.8f, 0.1f, 0.2f, AI_MATKEY_COLOR_DIFFUSE);
    expectColor(mapAssetMaterial(m, {}).material.color, 0.8f, 0.1f, 0.2f);
}

TEST(AssetMaterial, NegativeColourComponentsBecomeZeroAndNanIsIgnored) {
    aiMaterial negative;
    addColor(negative, -0.5f, 0.3f, 2.0f, AI_MATKEY_COLOR_DIFFUSE);
    expectColor(mapAssetMaterial(negative, {}).material.color, 0.0f, 0.3f, 2.0f);

    aiMaterial nan;
    addColor(nan, std::nanf(""), 0.3f, 0.3f, AI_MATKEY_BASE_COLOR);
    addColor(nan, 0.1f, 0.2f, 0.3f, AI_MATKEY_COLOR_DIFFUSE);
    const AssetMaterial a = mapAssetMaterial(nan, {});
    expectColor(a.material.color, 0.1f, 0.2f, 0.3f);  // the diffuse fallback
    EXPECT_TRUE(hasNote(a, "base colour is not a finite colour")) << allNotes(a);
}

TEST(AssetMaterial, MetallicRoughnessBecomeMirrorAndPhong) {
    aiMaterial m;
    addNumber(m, 0.3f, AI_MATKEY_METALLIC_FACTOR);
    addNumber(m, 0.4f, AI_MATKEY_ROUGHNESS_FACTOR);
    // Phong terms a glTF material also carries must not win over the PBR ones.
    addColor(m, 1.0f, 1.0f, 1.0f, AI_MATKEY_COLOR_SPECULAR);
    addNumber(m, 360.0f, AI_MATKEY_SHININESS);
    const AssetMaterial a = mapAssetMaterial(m, {});
    // reflectivity 0.3 * (1 - 0.4); specular 1 - 0.4; shininess 0.5 / 0.4^4 - 0.5, with
    // 0.4^4 = 0.0256, 0.5 / 0.0256 = 19.53125.
    EXPECT_NEAR(a.material.reflectivity, 0.18f, kTol);
    EXPECT_NEAR(a.material.specular, 0.6f, kTol);
    EXPECT_NEAR(a.material.shininess, 19.03125f, 1e-3f);
    EXPECT_NEAR(a.material.transparency, 0.0f, kTol);
    EXPECT_TRUE(hasNote(a, "metallic 0.3 and roughness 0.4 became reflectivity 0.18"))
        << allNotes(a);
}

TEST(AssetMaterial, RoughnessBoundsGiveShininessBounds) {
    aiMaterial smooth;
    addNumber(smooth, 1.0f, AI_MATKEY_METALLIC_FACTOR);
    addNumber(smooth, 0.0f, AI_MATKEY_ROUGHNESS_FACTOR);
    const Material s = mapAssetMaterial(smooth, {}).material;
    EXPECT_NEAR(s.reflectivity, 1.0f, kTol);
    EXPECT_NEAR(s.specular, 1.0f, kTol);
    EXPECT_NEAR(s.shininess, 10000.0f, 1e-2f);

    aiMaterial rough;
    addNumber(rough, 0.0f, AI_MATKEY_METALLIC_FACTOR);
    addNumber(rough, 1.0f, AI_MATKEY_ROUGHNESS_FACTOR);
    const AssetMaterial ra = mapAssetMaterial(rough, {});
    const Material& r = ra.material;
    EXPECT_NEAR(r.reflectivity, 0.0f, kTol);
    EXPECT_NEAR(r.specular, 0.0f, kTol);
    EXPECT_NEAR(r.shininess, 1.0f, kTol);           // 0.5 / 1 - 0.5 = 0, raised to 1
    EXPECT_TRUE(ra.notes.empty()) << allNotes(ra);  // a matte dielectric loses nothing

    aiMaterial outside;  // out of [0, 1]: clamped
    addNumber(outside, 2.0f, AI_MATKEY_METALLIC_FACTOR);
    addNumber(outside, -1.0f, AI_MATKEY_ROUGHNESS_FACTOR);
    EXPECT_NEAR(mapAssetMaterial(outside, {}).material.reflectivity, 1.0f, kTol);
}

TEST(AssetMaterial, MetallicAloneTakesGltfDefaultRoughnessOne) {
    aiMaterial m;
    addNumber(m, 0.5f, AI_MATKEY_METALLIC_FACTOR);
    const Material r = mapAssetMaterial(m, {}).material;
    EXPECT_NEAR(r.reflectivity, 0.0f, kTol);  // 0.5 * (1 - 1)
    EXPECT_NEAR(r.specular, 0.0f, kTol);
    EXPECT_NEAR(r.shininess, 1.0f, kTol);
}

TEST(AssetMaterial, RoughnessAloneIsFbxsAndKeepsPhong) {
    // What assimp 5.2.5 makes of an FBX Phong material with Ks 0.5 and exponent 32.
    aiMaterial m;
    addColor(m, 0.5f, 0.5f, 0.5f, AI_MATKEY_COLOR_SPECULAR);
    addNumber(m, 32.0f, AI_MATKEY_SHININESS);
    addNumber(m, 1.0f - std::sqrt(32.0f) / 10.0f, AI_MATKEY_ROUGHNESS_FACTOR);
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_NEAR(a.material.reflectivity, 0.0f, kTol);
    EXPECT_NEAR(a.material.specular, 0.5f, kTol);
    EXPECT_NEAR(a.material.shininess, 32.0f, kTol);
    EXPECT_FALSE(hasNote(a, "roughness")) << allNotes(a);
}

TEST(AssetMaterial, NonFiniteMetallicIsIgnoredWithANote) {
    aiMaterial m;
    addNumber(m, std::numeric_limits<float>::infinity(), AI_MATKEY_METALLIC_FACTOR);
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_NEAR(a.material.reflectivity, 0.0f, kTol);
    EXPECT_TRUE(hasNote(a, "metallic is not a finite number")) << allNotes(a);
}

TEST(AssetMaterial, MtlKsAndNsBecomeSpecularAndShininess) {
    aiMaterial grey;
    addColor(grey, 0.5f, 0.5f, 0.5f, AI_MATKEY_COLOR_SPECULAR);
    addNumber(grey, 50.0f, AI_MATKEY_SHININESS);
    const AssetMaterial g = mapAssetMaterial(grey, {});
    EXPECT_NEAR(g.material.specular, 0.5f, kTol);
    EXPECT_NEAR(g.material.shininess, 50.0f, kTol);
    EXPECT_NEAR(g.material.reflectivity, 0.0f, kTol);
    EXPECT_TRUE(g.notes.empty()) << allNotes(g);

    aiMaterial red;  // a coloured highlight becomes a white one of the colour's luminance
    addColor(red, 1.0f, 0.0f, 0.0f, AI_MATKEY_COLOR_SPECULAR);
    const AssetMaterial r = mapAssetMaterial(red, {});
    EXPECT_NEAR(r.material.specular, 0.2126f, kTol);
    EXPECT_TRUE(hasNote(r, "became a white highlight of weight 0.2126")) << allNotes(r);
}

TEST(AssetMaterial, SpecularStrengthScalesAndTheWeightIsClamped) {
    aiMaterial m;
    addColor(m, 0.25f, 0.25f, 0.25f, AI_MATKEY_COLOR_SPECULAR);
    addNumber(m, 2.0f, AI_MATKEY_SHININESS_STRENGTH);
    EXPECT_NEAR(mapAssetMaterial(m, {}).material.specular, 0.5f, kTol);
    aiMaterial bright;
    addColor(bright, 3.0f, 3.0f, 3.0f, AI_MATKEY_COLOR_SPECULAR);
    addNumber(bright, 20000.0f, AI_MATKEY_SHININESS);
    const Material b = mapAssetMaterial(bright, {}).material;
    EXPECT_NEAR(b.specular, 1.0f, kTol);
    EXPECT_NEAR(b.shininess, 10000.0f, kTol);
}

TEST(AssetMaterial, PhongReflectivityIsKept) {
    aiMaterial m;
    addNumber(m, 0.35f, AI_MATKEY_REFLECTIVITY);
    EXPECT_NEAR(mapAssetMaterial(m, {}).material.reflectivity, 0.35f, kTol);
}

TEST(AssetMaterial, TransmissionAndIorBecomeGlass) {
    aiMaterial m;
    addNumber(m, 0.0f, AI_MATKEY_METALLIC_FACTOR);
    addNumber(m, 0.0f, AI_MATKEY_ROUGHNESS_FACTOR);
    addNumber(m, 1.0f, AI_MATKEY_TRANSMISSION_FACTOR);
    addNumber(m, 1.33f, AI_MATKEY_REFRACTI);
    const Material g = mapAssetMaterial(m, {}).material;
    EXPECT_NEAR(g.transparency, 1.0f, kTol);
    EXPECT_NEAR(g.reflectivity, 0.0f, kTol);
    EXPECT_NEAR(g.ior, 1.33f, kTol);
}

TEST(AssetMaterial, TransmissionWithoutIorTakesGltfDefault) {
    aiMaterial m;
    addNumber(m, 0.6f, AI_MATKEY_TRANSMISSION_FACTOR);
    const Material g = mapAssetMaterial(m, {}).material;
    EXPECT_NEAR(g.transparency, 0.6f, kTol);
    EXPECT_NEAR(g.ior, 1.5f, kTol);
}

TEST(AssetMaterial, MetalTakesItsShareFromTransmission) {
    aiMaterial m;
    addNumber(m, 0.5f, AI_MATKEY_METALLIC_FACTOR);
    addNumber(m, 0.0f, AI_MATKEY_ROUGHNESS_FACTOR);
    addNumber(m, 0.8f, AI_MATKEY_TRANSMISSION_FACTOR);
    const Material g = mapAssetMaterial(m, {}).material;
    EXPECT_NEAR(g.reflectivity, 0.5f, kTol);  // 0.5 * (1 - 0)
    EXPECT_NEAR(g.transparency, 0.4f, kTol);  // 0.8 * (1 - 0.5)
}

TEST(AssetMaterial, MtlDissolveWithNiBends) {
    aiMaterial m;
    addNumber(m, 0.25f, AI_MATKEY_OPACITY);
    addNumber(m, 1.45f, AI_MATKEY_REFRACTI);
    const Material g = mapAssetMaterial(m, {}).material;
    EXPECT_NEAR(g.transparency, 0.75f, kTol);
    EXPECT_NEAR(g.ior, 1.45f, kTol);
}

TEST(AssetMaterial, OpacityWithoutIorGoesStraightThrough) {
    aiMaterial m;
    addNumber(m, 0.4f, AI_MATKEY_OPACITY);
    const Material g = mapAssetMaterial(m, {}).material;
    EXPECT_NEAR(g.transparency, 0.6f, kTol);
    EXPECT_NEAR(g.ior, 1.0f, kTol);
}

TEST(AssetMaterial, TransparencyFactorWhenNoOpacity) {
    aiMaterial m;
    addNumber(m, 0.3f, AI_MATKEY_TRANSPARENCYFACTOR);
    EXPECT_NEAR(mapAssetMaterial(m, {}).material.transparency, 0.3f, kTol);
    aiMaterial both;  // opacity wins
    addNumber(both, 0.3f, AI_MATKEY_TRANSPARENCYFACTOR);
    addNumber(both, 0.9f, AI_MATKEY_OPACITY);
    EXPECT_NEAR(mapAssetMaterial(both, {}).material.transparency, 0.1f, kTol);
}

TEST(AssetMaterial, GltfAlphaCountsOnlyWhenBlending) {
    for (const char* mode : {"OPAQUE", "MASK", "BLEND"}) {
        aiMaterial m;
        addNumber(m, 0.5f, AI_MATKEY_OPACITY);
        addString(m, mode, AI_MATKEY_GLTF_ALPHAMODE);
        const AssetMaterial a = mapAssetMaterial(m, {});
        const bool blend = std::string(mode) == "BLEND";
        EXPECT_NEAR(a.material.transparency, blend ? 0.5f : 0.0f, kTol) << mode;
        EXPECT_EQ(hasNote(a, "alpha cut-out"), std::string(mode) == "MASK") << mode;
    }
}

TEST(AssetMaterial, TransparencyGivesWayToReflectivity) {
    aiMaterial m;
    addNumber(m, 0.7f, AI_MATKEY_REFLECTIVITY);
    addNumber(m, 0.5f, AI_MATKEY_OPACITY);
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_NEAR(a.material.reflectivity, 0.7f, kTol);
    EXPECT_NEAR(a.material.transparency, 0.3f, kTol);
    EXPECT_TRUE(hasNote(a, "transparency 0.5 became 0.3")) << allNotes(a);
}

TEST(AssetMaterial, NonPositiveIorIsIgnored) {
    aiMaterial m;
    addNumber(m, 0.5f, AI_MATKEY_TRANSMISSION_FACTOR);
    addNumber(m, -2.0f, AI_MATKEY_REFRACTI);
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_NEAR(a.material.ior, 1.5f, kTol);
    EXPECT_TRUE(hasNote(a, "ior -2 is not positive")) << allNotes(a);
}

TEST(AssetMaterial, EmissiveIsNoted) {
    aiMaterial m;
    addColor(m, 1.0f, 0.5f, 0.0f, AI_MATKEY_COLOR_EMISSIVE);
    EXPECT_TRUE(hasNote(mapAssetMaterial(m, {}), "emissive colour (1, 0.5, 0)"));
    aiMaterial black;
    addColor(black, 0.0f, 0.0f, 0.0f, AI_MATKEY_COLOR_EMISSIVE);
    EXPECT_TRUE(mapAssetMaterial(black, {}).notes.empty());
}

TEST(AssetMaterial, BaseColourTextureFileWinsOverDiffuseTexture) {
    aiMaterial m;
    addString(m, "other.png", AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
    addString(m, "tex/a.png", AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
    AssetTextureContext context;
    context.assetDir = "/assets/box";
    const AssetMaterial a = mapAssetMaterial(m, context);
    EXPECT_EQ(a.texture.source, AssetTexture::Source::File);
    EXPECT_EQ(a.texture.path, "tex/a.png");
    const auto* t = std::get_if<ImageTexture>(&a.material.pattern);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->image.file, "tex/a.png");
    EXPECT_EQ(t->image.resolvedPath, "/assets/box/tex/a.png");
    EXPECT_EQ(t->scaleU, 1.0f);
    EXPECT_EQ(t->offsetV, 0.0f);
    EXPECT_TRUE(a.notes.empty()) << allNotes(a);
}

TEST(AssetMaterial, DiffuseTextureWithBackslashesAndAbsolutePaths) {
    aiMaterial m;
    addString(m, "maps\\wood.jpg", AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
    AssetTextureContext context;
    context.assetDir = "/assets/obj";
    const AssetMaterial a = mapAssetMaterial(m, context);
    const auto* t = std::get_if<ImageTexture>(&a.material.pattern);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->image.file, "maps/wood.jpg");
    EXPECT_EQ(t->image.resolvedPath, "/assets/obj/maps/wood.jpg");

    aiMaterial absolute;
    addString(absolute, "/textures/../stone.png", AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
    const AssetMaterial b = mapAssetMaterial(absolute, context);
    const auto* s = std::get_if<ImageTexture>(&b.material.pattern);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->image.resolvedPath, "/stone.png");
}

TEST(AssetMaterial, EmbeddedTextureByIndexAndByName) {
    AssetTextureContext context;
    context.embeddedNames = {"", "C:\\art\\wood.jpg"};
    aiMaterial star;
    addString(star, "*1", AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
    const AssetMaterial a = mapAssetMaterial(star, context);
    EXPECT_EQ(a.texture.source, AssetTexture::Source::Embedded);
    EXPECT_EQ(a.texture.embeddedIndex, 1);
    EXPECT_TRUE(a.texture.look.image.empty());
    EXPECT_EQ(a.material.pattern.index(), 0u);  // until the importer extracts it

    aiMaterial named;
    addString(named, "textures/wood.jpg", AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
    const AssetMaterial b = mapAssetMaterial(named, context);
    EXPECT_EQ(b.texture.source, AssetTexture::Source::Embedded);
    EXPECT_EQ(b.texture.embeddedIndex, 1);
}

TEST(AssetMaterial, EmbeddedIndexOutOfRangeLeavesItUntextured) {
    AssetTextureContext context;
    context.embeddedNames = {"a.png", "b.png"};
    for (const char* path : {"*2", "*x", "*"}) {
        aiMaterial m;
        addString(m, path, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
        const AssetMaterial a = mapAssetMaterial(m, context);
        EXPECT_EQ(a.texture.source, AssetTexture::Source::None) << path;
        EXPECT_EQ(a.material.pattern.index(), 0u) << path;
        EXPECT_TRUE(hasNote(a, "but the asset holds 2")) << path << "\n" << allNotes(a);
    }
}

TEST(AssetMaterial, UvChannelIsCarriedAndNoted) {
    aiMaterial m;
    addString(m, "a.png", AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
    int channel = 1;
    m.AddProperty(&channel, 1, AI_MATKEY_UVWSRC(aiTextureType_BASE_COLOR, 0));
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_EQ(a.texture.uvChannel, 1u);
    EXPECT_TRUE(hasNote(a, "UV channel 1")) << allNotes(a);
}

TEST(AssetMaterial, TextureTransformWithoutRotationBecomesScaleAndOffset) {
    aiMaterial m;
    addString(m, "a.png", AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
    // What assimp 5.2.5 makes of glTF's {"scale": [1.5, 2], "offset": [0.25, 0.1]}: V is
    // flipped, so the V offset is 1 - 2 - 0.1 (see the header).
    aiUVTransform uv;
    uv.mScaling = aiVector2D(1.5f, 2.0f);
    uv.mTranslation = aiVector2D(0.25f, 1.0f - 2.0f - 0.1f);
    m.AddProperty(&uv, 1, AI_MATKEY_UVTRANSFORM(aiTextureType_BASE_COLOR, 0));
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_TRUE(a.texture.hasTransform);
    const auto* t = std::get_if<ImageTexture>(&a.material.pattern);
    ASSERT_NE(t, nullptr);
    EXPECT_NEAR(t->scaleU, 1.5f, kTol);
    EXPECT_NEAR(t->scaleV, 2.0f, kTol);
    EXPECT_NEAR(t->offsetU, 0.25f, kTol);
    EXPECT_NEAR(t->offsetV, -1.1f, kTol);
    EXPECT_TRUE(a.notes.empty()) << allNotes(a);
}

TEST(AssetMaterial, RotatedTextureTransformIsCarriedButNotApplied) {
    aiMaterial m;
    addString(m, "a.png", AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
    aiUVTransform uv;
    uv.mScaling = aiVector2D(2.0f, 2.0f);
    uv.mTranslation = aiVector2D(0.1f, 0.2f);
    uv.mRotation = 0.3f;
    m.AddProperty(&uv, 1, AI_MATKEY_UVTRANSFORM(aiTextureType_BASE_COLOR, 0));
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_TRUE(a.texture.hasTransform);
    EXPECT_NEAR(a.texture.transform.rotation, 0.3f, kTol);
    EXPECT_NEAR(a.texture.transform.scaleU, 2.0f, kTol);
    EXPECT_EQ(a.texture.look.scaleU, 1.0f);
    EXPECT_EQ(a.texture.look.offsetU, 0.0f);
    EXPECT_TRUE(hasNote(a, "rotates by 0.3 rad")) << allNotes(a);
}

TEST(AssetMaterial, ClampedWrapModeIsNoted) {
    aiMaterial m;
    addString(m, "a.png", AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
    int clamp = aiTextureMapMode_Clamp, wrap = aiTextureMapMode_Wrap;
    m.AddProperty(&clamp, 1, AI_MATKEY_MAPPINGMODE_U(aiTextureType_DIFFUSE, 0));
    m.AddProperty(&wrap, 1, AI_MATKEY_MAPPINGMODE_V(aiTextureType_DIFFUSE, 0));
    const AssetMaterial a = mapAssetMaterial(m, {});
    EXPECT_TRUE(hasNote(a, "clamps in u")) << allNotes(a);
    EXPECT_FALSE(hasNote(a, "in v")) << allNotes(a);
}

TEST(AssetMaterial, ColourFactorUnderATextureIsNoted) {
    aiMaterial tinted;
    addColor(tinted, 0.8f, 0.8f, 0.8f, AI_MATKEY_COLOR_DIFFUSE);
    addString(tinted, "a.png", AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
    const AssetMaterial a = mapAssetMaterial(tinted, {});
    expectColor(a.material.color, 0.8f, 0.8f, 0.8f);  // kept for when the texture goes
    EXPECT_TRUE(hasNote(a, "multiplies the texture")) << allNotes(a);
    aiMaterial white;
    addColor(white, 1.0f, 1.0f, 1.0f, AI_MATKEY_COLOR_DIFFUSE);
    addString(white, "a.png", AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
    EXPECT_TRUE(mapAssetMaterial(white, {}).notes.empty());
}

}  // namespace
}  // namespace rs
