// An asset's lights and cameras (io/asset_lights.h): glTF files written here and read through
// the assimp the project links (5.2.5 on Debian), a scene built by hand for what glTF cannot
// hold, and one of Debian's assimp test models when it is installed. Expected values are
// closed forms of the numbers the files say.
#include "io/asset_lights.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "io/asset_looks.h"
#include "io/mesh_io.h"

namespace rs {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kPiD = 3.14159265358979323846;
constexpr float kTol = 1e-5f;

double deg(double radians) {
    return radians * 180.0 / kPiD;
}

/// glTF's quaternion [x, y, z, w] for a rotation by `radians` about the X axis.
json rotationX(double radians) {
    return json::array({std::sin(radians / 2), 0.0, 0.0, std::cos(radians / 2)});
}

void expectNear(const Vec3& got, double x, double y, double z, const char* what) {
    EXPECT_NEAR(got.x, x, kTol) << what;
    EXPECT_NEAR(got.y, y, kTol) << what;
    EXPECT_NEAR(got.z, z, kTol) << what;
}

bool anyNoteHas(const AssetLightsAndCameras& found, const std::string& a, const std::string& b) {
    for (const std::string& note : found.notes)
        if (note.find(a) != std::string::npos && note.find(b) != std::string::npos) return true;
    return false;
}

const Light* lightNamed(const AssetLightsAndCameras& found, const std::string& name) {
    for (const Light& l : found.lights)
        if (l.name == name) return &l;
    return nullptr;
}

const AssetCamera* cameraNamed(const AssetLightsAndCameras& found, const std::string& name) {
    for (const AssetCamera& c : found.cameras)
        if (c.name == name) return &c;
    return nullptr;
}

// The angles of the glTF written below (radians).
constexpr double kSpotInner = 0.2, kSpotOuter = 0.6;
constexpr double kSunTilt = -kPiD / 4, kSpotTilt = -kPiD / 2, kCameraTilt = -kPiD / 6;
constexpr double kYfov = 0.8, kAspect = 1.5, kYfovNoAspect = 0.7;

class AssetLightsGltf : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern =
            (fs::temp_directory_path() / "raystudio-asset-lights-XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    /// A glTF with one triangle (tri.bin next to it), four punctual lights and three
    /// cameras on nodes, two of them under a parent that moves and scales. `shareBulb`: the
    /// light under the parent is the first node's light, not one of its own.
    std::string writeGltf(bool shareBulb = false) {
        const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        const std::uint16_t indices[4] = {0, 1, 2, 0};
        std::ofstream bin(dir_ / "tri.bin", std::ios::binary);
        bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
        bin.write(reinterpret_cast<const char*>(indices), sizeof indices);
        bin.close();

        json lights = json::array();
        lights.push_back(
            {{"name", "bulb"}, {"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 4.0}});
        lights.push_back(
            {{"name", "stage"},
             {"type", "spot"},
             {"intensity", 2.0},
             {"spot", {{"innerConeAngle", kSpotInner}, {"outerConeAngle", kSpotOuter}}}});
        lights.push_back({{"name", "sun"}, {"type", "directional"}, {"intensity", 3.0}});
        // assimp 5.2.5 keeps one aiLight per glTF light, named after the last node using it,
        // so the light under the parent is a light of its own.
        lights.push_back({{"name", "bulb 2"}, {"type", "point"}});
        auto lightOn = [](int i) { return json{{"KHR_lights_punctual", {{"light", i}}}}; };
        json nodes = json::array();
        nodes.push_back({{"name", "Tri"}, {"mesh", 0}});
        nodes.push_back({{"name", "Bulb"}, {"translation", {1, 2, 3}}, {"extensions", lightOn(0)}});
        nodes.push_back({{"name", "Stage"},
                         {"translation", {0, 4, 0}},
                         {"rotation", rotationX(kSpotTilt)},
                         {"extensions", lightOn(1)}});
        nodes.push_back(
            {{"name", "Sun"}, {"rotation", rotationX(kSunTilt)}, {"extensions", lightOn(2)}});
        nodes.push_back({{"name", "Eye"},
                         {"translation", {0, 1, 5}},
                         {"rotation", rotationX(kCameraTilt)},
                         {"camera", 0}});
        // A parent moved by (10, 0, 0) and scaled by 2 with a light and a camera under it.
        nodes.push_back({{"name", "Rig"},
                         {"translation", {10, 0, 0}},
                         {"scale", {2, 2, 2}},
                         {"children", {6, 7}}});
        nodes.push_back({{"name", "RigBulb"},
                         {"translation", {1, 2, 3}},
                         {"extensions", lightOn(shareBulb ? 0 : 3)}});
        nodes.push_back({{"name", "RigEye"}, {"translation", {0, 0, 1}}, {"camera", 1}});
        nodes.push_back({{"name", "Flat"}, {"translation", {0, 3, 0}}, {"camera", 2}});

        json gltf = {
            {"asset", {{"version", "2.0"}}},
            {"extensionsUsed", {"KHR_lights_punctual"}},
            {"extensions", {{"KHR_lights_punctual", {{"lights", lights}}}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0, 1, 2, 3, 4, 5, 8}}}}},
            {"nodes", nodes},
            {"cameras",
             {{{"type", "perspective"},
               {"perspective", {{"yfov", kYfov}, {"aspectRatio", kAspect}, {"znear", 0.1}}}},
              {{"type", "perspective"}, {"perspective", {{"yfov", kYfovNoAspect}, {"znear", 0.1}}}},
              {{"type", "orthographic"},
               {"orthographic", {{"xmag", 2.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}}}},
            {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
            {"buffers", {{{"byteLength", 44}, {"uri", "tri.bin"}}}},
            {"bufferViews",
             {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
              {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
            {"accessors",
             {{{"bufferView", 0},
               {"componentType", 5126},
               {"count", 3},
               {"type", "VEC3"},
               {"min", {0, 0, 0}},
               {"max", {1, 1, 0}}},
              {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}}};
        const fs::path file = dir_ / "lights.gltf";
        std::ofstream(file) << gltf.dump(1);
        return file.string();
    }

    const aiScene* read(const std::string& file) {
        const aiScene* scene = importer_.ReadFile(file, aiProcess_ValidateDataStructure);
        EXPECT_NE(scene, nullptr) << importer_.GetErrorString();
        return scene;
    }

    fs::path dir_;
    Assimp::Importer importer_;
};

// What assimp 5.2.5 does with KHR_lights_punctual (assimp issue 6364): the light's own
// position is the origin and its node carries the translation; a reader that takes
// aiLight::mPosition alone puts every light at the origin. Its camera, though, gets the node's
// translation copied into mPosition as well as in the node.
TEST_F(AssetLightsGltf, Assimp525KeepsPunctualPositionsInTheNodes) {
    const aiScene* scene = read(writeGltf());
    ASSERT_NE(scene, nullptr);
    ASSERT_EQ(scene->mNumLights, 4u);
    const aiLight& bulb = *scene->mLights[0];
    EXPECT_EQ(bulb.mPosition, aiVector3D(0, 0, 0));
    const aiNode* node = scene->mRootNode->FindNode(bulb.mName);
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(node->mTransformation.a4, 1.0f);
    EXPECT_EQ(node->mTransformation.b4, 2.0f);
    EXPECT_EQ(node->mTransformation.c4, 3.0f);
    ASSERT_GE(scene->mNumCameras, 1u);
    EXPECT_EQ(scene->mCameras[0]->mPosition, aiVector3D(0, 1, 5));
}

// Two more 5.2.5 findings the header and FORMAT.md rely on: aiProcess_PreTransformVertices
// moves a glTF camera by its node's transform on top of the translation already copied into
// its position, and a glTF light used by two nodes arrives once, named after (and so placed
// at) the last of them.
TEST_F(AssetLightsGltf, Assimp525PreTransformMovesGltfCamerasTwiceAndSharedLightsOnce) {
    const std::string file = writeGltf(true);
    Assimp::Importer pretransformed;
    const aiScene* baked = pretransformed.ReadFile(file, aiProcess_PreTransformVertices);
    ASSERT_NE(baked, nullptr) << pretransformed.GetErrorString();
    ASSERT_GE(baked->mNumCameras, 1u);
    // The node (translation (0, 1, 5), rotation t about X) applied to (0, 1, 5) once more.
    const aiVector3D& twice = baked->mCameras[0]->mPosition;
    const double t = kCameraTilt;
    EXPECT_NEAR(twice.x, 0.0, kTol);
    EXPECT_NEAR(twice.y, 1 + std::cos(t) - 5 * std::sin(t), kTol);
    EXPECT_NEAR(twice.z, 5 + std::sin(t) + 5 * std::cos(t), kTol);

    const aiScene* scene = read(file);
    ASSERT_NE(scene, nullptr);
    const AssetLightsAndCameras found = assetLightsAndCameras(*scene, Mat4(1.0f));
    EXPECT_EQ(lightNamed(found, "Bulb"), nullptr);
    const Light* rig = lightNamed(found, "RigBulb");
    ASSERT_NE(rig, nullptr);
    expectNear(rig->position, 12, 4, 6, "the shared light at its last node");
}

TEST_F(AssetLightsGltf, PointLightLandsAtItsNodeWithItsColourAndIntensity) {
    const aiScene* scene = read(writeGltf());
    ASSERT_NE(scene, nullptr);
    const AssetLightsAndCameras found = assetLightsAndCameras(*scene, Mat4(1.0f));
    const Light* bulb = lightNamed(found, "Bulb");
    ASSERT_NE(bulb, nullptr);
    EXPECT_EQ(bulb->type, LightType::Point);
    expectNear(bulb->position, 1, 2, 3, "at its node's translation, not the origin");
    // color [1, 0.5, 0.25] * intensity 4 in assimp: split back.
    expectNear(bulb->color, 1.0, 0.5, 0.25, "colour");
    EXPECT_NEAR(bulb->intensity, 4.0f, kTol);
    EXPECT_TRUE(anyNoteHas(found, "'Bulb'", "fall-off"));
    // Under the parent: 2 * (1, 2, 3) + (10, 0, 0), composed from the root down.
    const Light* rig = lightNamed(found, "RigBulb");
    ASSERT_NE(rig, nullptr);
    expectNear(rig->position, 12, 4, 6, "under a moved and scaled parent");
}

TEST_F(AssetLightsGltf, SpotLightPointsDownItsNodesMinusZWithHalfAngles) {
    const aiScene* scene = read(writeGltf());
    ASSERT_NE(scene, nullptr);
    const AssetLightsAndCameras found = assetLightsAndCameras(*scene, Mat4(1.0f));
    const Light* spot = lightNamed(found, "Stage");
    ASSERT_NE(spot, nullptr);
    EXPECT_EQ(spot->type, LightType::Spot);
    expectNear(spot->position, 0, 4, 0, "position");
    // -Z rotated by t about X: (0, sin t, -cos t); t = -90 degrees aims it straight down.
    const Vec3 axis = glm::normalize(spot->target - spot->position);
    expectNear(axis, 0, std::sin(kSpotTilt), -std::cos(kSpotTilt), "axis");
    // glTF's cone angles are already half-angles.
    EXPECT_NEAR(spot->coneRadius, deg(kSpotInner), 1e-4);
    EXPECT_NEAR(spot->coneFalloff, deg(kSpotOuter), 1e-4);
    expectNear(spot->color, 1, 1, 1, "white");
    EXPECT_NEAR(spot->intensity, 2.0f, kTol);
}

TEST_F(AssetLightsGltf, DirectionalLightTravelsDownItsNodesMinusZ) {
    const aiScene* scene = read(writeGltf());
    ASSERT_NE(scene, nullptr);
    const AssetLightsAndCameras found = assetLightsAndCameras(*scene, Mat4(1.0f));
    const Light* sun = lightNamed(found, "Sun");
    ASSERT_NE(sun, nullptr);
    EXPECT_EQ(sun->type, LightType::Directional);
    expectNear(sun->direction, 0, std::sin(kSunTilt), -std::cos(kSunTilt), "direction");
    EXPECT_NEAR(sun->intensity, 3.0f, kTol);
    EXPECT_FALSE(anyNoteHas(found, "'Sun'", "fall-off"));
}

TEST_F(AssetLightsGltf, CameraAtItsNodeLookingDownMinusZWithItsVerticalFov) {
    const aiScene* scene = read(writeGltf());
    ASSERT_NE(scene, nullptr);
    const AssetLightsAndCameras found = assetLightsAndCameras(*scene, Mat4(1.0f));
    const AssetCamera* eye = cameraNamed(found, "Eye");
    ASSERT_NE(eye, nullptr);
    const Camera& c = eye->camera;
    EXPECT_EQ(c.projection, Projection::Perspective);
    // (0, 1, 5), not the (0, 2, 10) of adding the node's translation twice.
    expectNear(c.position, 0, 1, 5, "position");
    expectNear(glm::normalize(c.target - c.position), 0, std::sin(kCameraTilt),
               -std::cos(kCameraTilt), "look");
    expectNear(glm::normalize(c.up), 0, std::cos(kCameraTilt), std::sin(kCameraTilt), "up");
    EXPECT_NEAR(c.fovY, deg(kYfov), 1e-4);
    // Without aspectRatio the yfov comes through as it is; under the parent, 2 * (0, 0, 1)
    // + (10, 0, 0).
    const AssetCamera* rig = cameraNamed(found, "RigEye");
    ASSERT_NE(rig, nullptr);
    EXPECT_NEAR(rig->camera.fovY, deg(kYfovNoAspect), 1e-4);
    expectNear(rig->camera.position, 10, 0, 2, "under the parent");
    // Orthographic: ymag 1 is half the visible height.
    const AssetCamera* flat = cameraNamed(found, "Flat");
    ASSERT_NE(flat, nullptr);
    EXPECT_EQ(flat->camera.projection, Projection::Orthographic);
    EXPECT_NEAR(flat->camera.orthoHeight, 2.0f, kTol);
    expectNear(flat->camera.position, 0, 3, 0, "orthographic camera's position");
}

TEST_F(AssetLightsGltf, LightsAndCamerasFollowTheAssetsPlacement) {
    const aiScene* scene = read(writeGltf());
    ASSERT_NE(scene, nullptr);
    // Rotate 90 degrees about Y, scale by 0.5, move by (5, 0, 0): (x, y, z) goes to
    // (5 + z / 2, y / 2, -x / 2), and directions to (z, y, -x).
    Mat4 placement = glm::translate(Mat4(1.0f), Vec3(5, 0, 0));
    placement = glm::scale(placement, Vec3(0.5f));
    placement = glm::rotate(placement, kPi / 2, Vec3(0, 1, 0));
    const AssetLightsAndCameras found = assetLightsAndCameras(*scene, placement);
    const Light* bulb = lightNamed(found, "Bulb");
    ASSERT_NE(bulb, nullptr);
    expectNear(bulb->position, 5 + 3 / 2.0, 2 / 2.0, -1 / 2.0, "point light placed");
    const Light* sun = lightNamed(found, "Sun");
    ASSERT_NE(sun, nullptr);
    expectNear(sun->direction, -std::cos(kSunTilt), std::sin(kSunTilt), 0, "sun turned");
    const Light* spot = lightNamed(found, "Stage");
    ASSERT_NE(spot, nullptr);
    expectNear(spot->position, 5, 2, 0, "spot placed");
    expectNear(glm::normalize(spot->target - spot->position), -std::cos(kSpotTilt),
               std::sin(kSpotTilt), 0, "spot turned");
    const AssetCamera* eye = cameraNamed(found, "Eye");
    ASSERT_NE(eye, nullptr);
    expectNear(eye->camera.position, 5 + 5 / 2.0, 1 / 2.0, 0, "camera placed");
    expectNear(glm::normalize(eye->camera.target - eye->camera.position), -std::cos(kCameraTilt),
               std::sin(kCameraTilt), 0, "camera turned");
    EXPECT_NEAR(eye->camera.fovY, deg(kYfov), 1e-4);  // a placement does not zoom
    const AssetCamera* flat = cameraNamed(found, "Flat");
    ASSERT_NE(flat, nullptr);
    EXPECT_NEAR(flat->camera.orthoHeight, 2.0f * 0.5f, kTol);
}

/// A scene as another importer (FBX, Collada) would leave it, for what glTF cannot say.
// The import proper: the child reads the lights and cameras before pre-transforming the
// vertices, sends them over the wire, and adopting them places them as the asset is placed.
TEST_F(AssetLightsGltf, ThroughTheImport_LightsAndCamerasArriveAndFollowThePlacement) {
    const MeshLoadResult r = loadMesh(writeGltf(), true);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_TRUE(r.asset);
    const Light* bulb = nullptr;
    for (const Light& l : r.asset->lights)
        if (l.name == "Bulb") bulb = &l;
    ASSERT_NE(bulb, nullptr);
    expectNear(bulb->position, 1, 2, 3, "bulb through the child");
    const AssetView* eye = nullptr;
    for (const AssetView& v : r.asset->views)
        if (v.name == "Eye") eye = &v;
    ASSERT_NE(eye, nullptr);
    expectNear(eye->camera.position, 0, 1, 5, "eye through the child");

    SceneDocument doc;
    Object taken;
    taken.name = "Bulb";  // an object already bears the light's name
    doc.addObject(taken);
    Object asset;
    asset.name = "asset";
    asset.geometry = MeshGeometry{};
    asset.transform.translate = Vec3(0, 5, 0);
    asset.transform.scale = Vec3(2);
    const ObjectId id = doc.addObject(asset);
    const std::vector<ObjectId> ids = adoptAssetLights(doc, id, *r.asset);
    EXPECT_EQ(ids.size(), r.asset->lights.size());
    const Light* placed = nullptr;
    for (const Light& l : doc.lights)
        if (l.name == "Bulb.001") placed = &l;
    ASSERT_NE(placed, nullptr);
    expectNear(placed->position, 2, 9, 6, "bulb placed (scaled 2, raised 5)");
    const Camera camera = placedAssetCamera(*eye, *doc.findObject(id));
    expectNear(camera.position, 0, 7, 10, "eye placed (scaled 2, raised 5)");
    EXPECT_NEAR(glm::length(camera.up), 1.0f, 1e-6f);
}

struct HandScene {
    aiScene scene;
    HandScene() {
        scene.mRootNode = new aiNode("root");
        scene.mRootNode->mTransformation =
            aiMatrix4x4(aiVector3D(1, 1, 1), aiQuaternion(), aiVector3D(0, 0, 1));
        const char* names[] = {"panel", "sky", "spot", "lonely"};
        scene.mRootNode->mNumChildren = 3;
        scene.mRootNode->mChildren = new aiNode*[3];
        for (int i = 0; i < 3; ++i) {
            scene.mRootNode->mChildren[i] = new aiNode(names[i]);
            scene.mRootNode->mChildren[i]->mParent = scene.mRootNode;
        }
        scene.mNumLights = 4;
        scene.mLights = new aiLight*[4];
        for (int i = 0; i < 4; ++i) {
            scene.mLights[i] = new aiLight;
            scene.mLights[i]->mName = names[i];
            scene.mLights[i]->mColorDiffuse = aiColor3D(1, 1, 1);
        }
        scene.mLights[0]->mType = aiLightSource_AREA;
        scene.mLights[1]->mType = aiLightSource_AMBIENT;
        scene.mLights[2]->mType = aiLightSource_SPOT;
        scene.mLights[2]->mDirection = aiVector3D(0, -1, 0);
        scene.mLights[2]->mAngleInnerCone = 0.4f;  // full angles, as assimp documents
        scene.mLights[2]->mAngleOuterCone = 1.2f;
        scene.mLights[3]->mType = aiLightSource_POINT;
        scene.mLights[3]->mPosition = aiVector3D(7, 8, 9);
        scene.mNumCameras = 1;
        scene.mCameras = new aiCamera*[1];
        scene.mCameras[0] = new aiCamera;
        scene.mCameras[0]->mName = "spot";  // shares the spot light's node
        scene.mCameras[0]->mPosition = aiVector3D(0, 0, 3);
        scene.mCameras[0]->mHorizontalFOV = 1.0f;
        scene.mCameras[0]->mAspect = 2.0f;
    }
};

TEST(AssetLights, UnsupportedLightsAreSkippedWithANote) {
    HandScene hand;
    const AssetLightsAndCameras found = assetLightsAndCameras(hand.scene, Mat4(1.0f));
    EXPECT_EQ(lightNamed(found, "panel"), nullptr);
    EXPECT_EQ(lightNamed(found, "sky"), nullptr);
    EXPECT_TRUE(anyNoteHas(found, "'panel'", "area light: skipped"));
    EXPECT_TRUE(anyNoteHas(found, "'sky'", "ambient light: skipped"));
    // No node of its name: its own position, and a note.
    const Light* lonely = lightNamed(found, "lonely");
    ASSERT_NE(lonely, nullptr);
    expectNear(lonely->position, 7, 8, 9, "own position");
    EXPECT_TRUE(anyNoteHas(found, "'lonely'", "no node"));
    EXPECT_EQ(found.lights.size(), 2u);
}

TEST(AssetLights, OtherImportersFullAnglesAreHalved) {
    HandScene hand;
    const AssetLightsAndCameras found = assetLightsAndCameras(hand.scene, Mat4(1.0f));
    const Light* spot = lightNamed(found, "spot");
    ASSERT_NE(spot, nullptr);
    expectNear(spot->position, 0, 0, 1, "by the root's translation");
    expectNear(glm::normalize(spot->target - spot->position), 0, -1, 0, "axis");
    EXPECT_NEAR(spot->coneRadius, deg(0.2), 1e-4);
    EXPECT_NEAR(spot->coneFalloff, deg(0.6), 1e-4);
    // A full horizontal angle of 1 radian at aspect 2: tan(v / 2) = tan(1 / 2) / 2.
    const AssetCamera* camera = cameraNamed(found, "spot");
    ASSERT_NE(camera, nullptr);
    EXPECT_NEAR(camera->camera.fovY, deg(2 * std::atan(std::tan(0.5) / 2)), 1e-4);
    expectNear(camera->camera.position, 0, 0, 4, "its own position, then its node's");
}

// Debian's assimp-testmodels (not shipped with the project; RAYSTUDIO_ASSIMP_MODELS names
// another copy): global_settings.fbx, Blender's default scene. Its binary records hold the lamp's
// and the camera's Lcl Translation and the camera's FocalLength (35 mm) and FilmHeight (0.70866 in
// = 18 mm).
TEST(AssetLights, FbxLampAndCameraArriveWhereTheFileSays) {
    const char* models = std::getenv("RAYSTUDIO_ASSIMP_MODELS");
    const std::string file =
        std::string(models ? models : "/usr/share/assimp/models") + "/FBX/global_settings.fbx";
    if (!fs::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(file, aiProcess_ValidateDataStructure);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    const AssetLightsAndCameras found = assetLightsAndCameras(*scene, Mat4(1.0f));
    const Light* lamp = lightNamed(found, "Lamp");
    ASSERT_NE(lamp, nullptr);
    EXPECT_EQ(lamp->type, LightType::Point);
    expectNear(lamp->position, 4.076245307922363, 5.903861999511719, -1.0054539442062378, "lamp");
    const AssetCamera* camera = cameraNamed(found, "Camera");
    ASSERT_NE(camera, nullptr);
    expectNear(camera->camera.position, 7.481131553649902, 5.34366512298584, 6.5076398849487305,
               "camera");
    EXPECT_NEAR(camera->camera.fovY, deg(2 * std::atan(9.0 / 35.0)), 1e-3);
}

}  // namespace
}  // namespace rs
