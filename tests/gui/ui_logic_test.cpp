// The designer's Qt-free-ish logic without a window: names for duplicates, the default scene.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <glm/gtc/matrix_transform.hpp>

#include "display/display_choice.h"
#include "display/display_frame.h"
#include "document/default_scene.h"
#include "document/placement.h"
#include "document/scene_edits.h"
#include "document/transform_edits.h"
#include "panels/dialog_folders.h"
#include "scene/parameters.h"
#include "snapshot/compiled_scene.h"
#include "viewport/transform_gizmo.h"
#include "viewport/view_projection.h"

using namespace rs;
using namespace rs::ui;

namespace {

ObjectId addBall(SceneDocument& doc, const std::string& name) {
    Object o;
    o.name = name;
    o.geometry = SphereGeometry{};
    return doc.addObject(std::move(o));
}

std::string nameOf(const SceneDocument& doc, ObjectId id) {
    if (const Object* o = doc.findObject(id)) return o->name;
    if (const Light* l = doc.findLight(id)) return l->name;
    return {};
}

}  // namespace

class UiLogicTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void duplicate_CountsOnFromTheCopysNumber();
    void duplicate_NamesWithoutAPlainNumberGetOneAppended();
    void defaultScene_BuildTree_FoundFromAnyExecutableFolder();
    void defaultScene_Installed_PrefersShareNextToTheExecutable();
    void materials_DeleteRefusedWhileUsed_RenameFollowsUsers_NamesValidated();
    void placement_RestsOnTheSurfaceHit_OrSnapsToTheFloorBelow();
    void placeInView_OnTheFloorInFront_ClearOfOthers_PlaneUnder_LightBelowTheCeiling();
    void fitScale_ScalesOnlyMeshesThatDoNotFitTheView();
    void sunGlyph_FromAFile_GoesUpstreamOfTheScene();
    void gizmoRings_StayInsideTheFrame_NearItsEdge();
    void displayAutomatic_PicksSoftwareOnSoftwareGL_OpenGLOnAGpu();
    void scaleAlongWorldX_StretchesTheAxisOfARotatedObjectThatLiesAlongX();
    void scaleAlongLocalAxes_MovesOtherObjectsAlongThoseAxes();
    void outlineShortcuts_AgreeWithOnOutlinePixelForPixel();
    void dialogFolders_OpenWhereTheUserLastChose_PerKindOfFile();
};

void UiLogicTest::materials_DeleteRefusedWhileUsed_RenameFollowsUsers_NamesValidated() {
    SceneDocument doc;
    const std::string red = addMaterial(doc);
    QCOMPARE(red, std::string("material"));
    const ObjectId a = addBall(doc, "a");
    addBall(doc, "b");
    QCOMPARE(assignMaterial(doc, {a}, red), 1);
    QCOMPARE(assignMaterial(doc, {a}, "no such"), 0);
    const std::string refused = deleteMaterial(doc, red);
    QVERIFY2(refused.find("used by \"a\"") != std::string::npos, refused.c_str());
    QCOMPARE(doc.materials.size(), std::size_t(1));

    const std::string copy = duplicateMaterial(doc, red);
    QCOMPARE(copy, std::string("material 2"));
    QVERIFY(renameMaterial(doc, red, copy).find("already named") != std::string::npos);
    QVERIFY(renameMaterial(doc, red, "").find("must not be empty") != std::string::npos);
    QCOMPARE(renameMaterial(doc, red, "a"), std::string());  // Objects are another list.
    QCOMPARE(doc.findObject(a)->material, std::string("a"));
    QCOMPARE(deleteMaterial(doc, copy), std::string());
    QCOMPARE(doc.materials.size(), std::size_t(1));

    // Many users: the first three by name, the rest counted.
    std::vector<ObjectId> balls;
    for (const char* n : {"c", "d", "e", "f"}) balls.push_back(addBall(doc, n));
    QCOMPARE(assignMaterial(doc, balls, "a"), 4);
    QCOMPARE(materialDeleteError(doc, "a"),
             std::string("\"a\" is used by \"a\", \"c\", \"d\" and 2 more; assign those another "
                         "material first"));

    // An imported asset whose parts have their own materials takes it as a whole.
    Object asset;
    asset.name = "asset";
    asset.material = "a";
    MeshGeometry parts;
    parts.partMaterials = {"a", ""};
    asset.geometry = parts;
    const ObjectId meshId = doc.addObject(std::move(asset));
    QCOMPARE(assignMaterial(doc, {meshId}, "a"), 1);
    QVERIFY(std::get<MeshGeometry>(doc.findObject(meshId)->geometry).partMaterials.empty());
    QCOMPARE(assignMaterial(doc, {meshId}, "a"), 0);
}

void UiLogicTest::placement_RestsOnTheSurfaceHit_OrSnapsToTheFloorBelow() {
    SceneDocument doc;
    Object floor;
    floor.name = "floor";
    floor.geometry = PlaneGeometry{Vec3(0.0f, -2.0f, 0.0f), Vec3(0, 1, 0)};
    doc.addObject(floor);
    Object wall;
    wall.name = "wall";
    wall.geometry = PlaneGeometry{Vec3(0.0f, 0.0f, -10.0f), Vec3(0, 0, 1)};
    doc.addObject(wall);
    const CompiledScene scene(doc);

    const Placement hit = placeAlong(&scene, Ray::make(Vec3(0.0f), Vec3(0, 0, -2)), 3.0f);
    QVERIFY(hit.onSurface);
    QCOMPARE(hit.distance, 10.0f);
    QVERIFY(hit.normal == Vec3(0, 0, 1));
    const ObjectId box = addShape(doc, ShapeKind::Box, hit.point);
    restOn(doc, box, hit);
    QCOMPARE(worldBounds(doc, box).min.z, -10.0f);  // Touching the wall, in front of it.
    QVERIFY(snapToFloor(doc, box, &scene, Vec3(0, 1, 0)));
    QCOMPARE(worldBounds(doc, box).min.y, -2.0f);
    QCOMPARE(worldBounds(doc, box).min.z, -10.0f);

    const Placement miss = placeAlong(&scene, Ray::make(Vec3(0.0f), Vec3(0, 1, 0)), 3.0f);
    QVERIFY(!miss.onSurface);
    QVERIFY(miss.point == Vec3(0.0f, 3.0f, 0.0f));
}

void UiLogicTest::placeInView_OnTheFloorInFront_ClearOfOthers_PlaneUnder_LightBelowTheCeiling() {
    // A room: floor y = 0, ceiling y = 6, back wall z = -12; a ball right where the view's
    // centre ray meets the floor's stand-in point (front of the view, 5 units).
    SceneDocument doc;
    const auto plane = [&](const char* name, Vec3 point, Vec3 normal) {
        Object o;
        o.name = name;
        o.geometry = PlaneGeometry{point, normal};
        doc.addObject(o);
    };
    plane("floor", Vec3(0.0f), Vec3(0, 1, 0));
    plane("ceiling", Vec3(0, 6, 0), Vec3(0, -1, 0));
    plane("back", Vec3(0, 0, -12), Vec3(0, 0, 1));
    Camera view;
    view.position = Vec3(0, 3, 2.5f);
    view.target = Vec3(0, 3, -6);  // 8.5 away: a new thing goes 5 units ahead
    Object ball;
    ball.name = "ball";
    ball.geometry = SphereGeometry{Vec3(0, 0.5f, -2.5f), 0.5f};
    const ObjectId ballId = doc.addObject(ball);
    const Vec3 up(0, 1, 0);
    auto placeNew = [&](ShapeKind kind) {
        const CompiledScene scene(doc);  // without the new object
        const ObjectId id = addShape(doc, kind, Vec3(0.0f));
        placeInView(doc, id, &scene, view, up, 16.0f / 9.0f);
        return id;
    };
    auto inFront = [&](const Vec3& p) {
        const Vec3 d = p - view.position;
        const float along = -d.z;  // the view looks along -Z
        const float halfFov = glm::radians(view.fovY) * 0.5f;
        return along > 0.0f && std::abs(d.x) < along * std::tan(halfFov) * 1.8f &&
               std::abs(d.y) < along * std::tan(halfFov);
    };
    const ObjectId first = placeNew(ShapeKind::Sphere);
    Aabb a = worldBounds(doc, first);
    QVERIFY(std::abs(a.min.y) < 1e-4f);  // resting on the floor
    QVERIFY(inFront(a.center()));
    QVERIFY(!a.overlaps(worldBounds(doc, ballId)));          // not inside or on the ball
    QVERIFY(a.min.z > -12.0f && a.max.z < view.position.z);  // between the view and the wall
    const ObjectId second = placeNew(ShapeKind::Box);
    const Aabb b = worldBounds(doc, second);
    QVERIFY(std::abs(b.min.y) < 1e-4f);
    QVERIFY(inFront(b.center()));
    QVERIFY(!b.overlaps(a) && !b.overlaps(worldBounds(doc, ballId)));  // no stacking
    // A plane: a floor under the scene, not a cut through it at eye height.
    const ObjectId floor = placeNew(ShapeKind::Plane);
    const auto& p = std::get<PlaneGeometry>(doc.findObject(floor)->geometry);
    QVERIFY(p.normal == up);
    QVERIFY(std::abs(p.point.y) < 1e-4f);
    // A light: above what is below the point in front (the ball's top, y = 1), a third of
    // the way from there to the ceiling.
    const CompiledScene scene(doc);
    const ObjectId lamp = addLight(doc, LightType::Point, Vec3(0.0f));
    const Vec3 ground = placeInView(doc, lamp, &scene, view, up, 16.0f / 9.0f);
    QVERIFY(std::abs(ground.y - 1.0f) < 1e-4f);
    QVERIFY(std::abs(doc.findLight(lamp)->position.y - (1.0f + 5.0f / 3.0f)) < 1e-3f);
    QVERIFY(inFront(doc.findLight(lamp)->position));
}

void UiLogicTest::fitScale_ScalesOnlyMeshesThatDoNotFitTheView() {
    Camera view;  // fov 55 degrees: about 1.04 units visible per unit of distance.
    const float visible = 2.0f * 10.0f * std::tan(glm::radians(view.fovY) / 2.0f);
    auto cube = [](float side) {
        Aabb b;
        b.expand(Vec3(-side / 2));
        b.expand(Vec3(side / 2));
        return b;
    };
    QCOMPARE(fitScale(cube(2.0f), view, 10.0f), 1.0f);
    const float big = fitScale(cube(150.0f), view, 10.0f);
    const float share = big * glm::length(cube(150.0f).extent()) / visible;
    QVERIFY2(std::abs(share - kFitViewShare) < 0.02f, qPrintable(QString::number(share)));
    QVERIFY(fitScale(cube(0.001f), view, 10.0f) > 100.0f);
    // A factor the Scale field could not show is clamped to its range.
    QCOMPARE(fitScale(cube(1e9f), view, 10.0f),
             float(findParameter(ParamKind::Transform, "scale")->softMin));
}

namespace {

/// The pixels `g` paints, drawn over a transparent `frame` with a margin of 200 pixels all
/// round: how many fall outside the frame, and how many outside g.bounds().
std::pair<int, int> paintedOutside(const TransformGizmo& g, const QRect& frame) {
    constexpr int kMargin = 200;
    QImage image(frame.size() + QSize(2 * kMargin, 2 * kMargin), QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    {
        QPainter p(&image);
        p.translate(kMargin - frame.left(), kMargin - frame.top());
        g.paint(p, std::nullopt);
    }
    const QRectF bounds = g.bounds();
    int outsideFrame = 0, outsideBounds = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (qAlpha(image.pixel(x, y)) == 0) continue;
            // The pixel's square in widget coordinates.
            const QRectF px(x - kMargin + frame.left(), y - kMargin + frame.top(), 1, 1);
            outsideFrame += !QRectF(frame).contains(px);
            outsideBounds += !bounds.contains(px);
        }
    return {outsideFrame, outsideBounds};
}

}  // namespace

void UiLogicTest::gizmoRings_StayInsideTheFrame_NearItsEdge() {
    // A 960 x 540 view, seen straight on and from two angles; pivots from the middle
    // to 40 pixels from an edge. The whole gizmo stays inside, every handle drawn can be
    // grabbed.
    const QSize size(960, 540);
    for (const Vec3 eye : {Vec3(0, 0, 5), Vec3(3, 3, 4), Vec3(-3, 2, 5)}) {
        Camera view;
        view.position = eye;
        view.target = Vec3(0, 0, 0);
        const ViewProjection projection(view, size, size, size);
        const QRect frame = projection.imageRect();
        QCOMPARE(frame, QRect(QPoint(0, 0), size));
        const QPointF points[] = {{480, 270}, {480, 180}, {480, 125}, {480, 90}, {480, 40},
                                  {60, 270},  {900, 270}, {480, 480}, {60, 60},  {900, 480}};
        for (const QPointF& at : points) {
            const QString where = QStringLiteral("pivot at (%1, %2), eye (%3, %4, %5)")
                                      .arg(at.x())
                                      .arg(at.y())
                                      .arg(eye.x)
                                      .arg(eye.y)
                                      .arg(eye.z);
            const Ray ray = projection.rayThrough(at);
            // On the plane through the origin facing the camera.
            const Vec3 n = glm::normalize(eye);
            const Vec3 pivot =
                ray.origin + ray.dir * (-glm::dot(ray.origin, n) / glm::dot(ray.dir, n));
            const TransformGizmo g(projection, pivot, Mat3(1.0f));
            QVERIFY2(g.valid(), qPrintable(where));
            const auto [outsideFrame, outsideBounds] = paintedOutside(g, frame);
            QVERIFY2(outsideFrame == 0,
                     qPrintable(
                         where +
                         QStringLiteral(": %1 pixels drawn outside the frame").arg(outsideFrame)));
            QVERIFY2(outsideBounds == 0,
                     qPrintable(
                         where +
                         QStringLiteral(": %1 pixels drawn outside bounds()").arg(outsideBounds)));
            QVERIFY2(QRectF(frame).contains(g.bounds()), qPrintable(where));
            // Every handle drawn is grabbed somewhere (where grabPoint says), inside the frame.
            // (Straight on, Z points along the ray from the view's centre: off the centre its
            // short arrow lies on the X or Y arrow, as in any 3D tool. Drawn only.)
            if (eye.x == 0.0f) continue;
            int shown = 0;
            for (int axis = 0; axis < 3; ++axis)
                for (const GizmoHandle h : {GizmoHandle{TransformKind::Move, axis, false},
                                            GizmoHandle{TransformKind::Move, axis, true},
                                            GizmoHandle{TransformKind::Scale, axis, false},
                                            GizmoHandle{TransformKind::Rotate, axis, false}}) {
                    if (!g.shows(h)) continue;
                    ++shown;
                    const QString what =
                        where + QStringLiteral(": handle %1/%2/%3 (kind/axis/plane)")
                                    .arg(int(h.kind))
                                    .arg(h.axis)
                                    .arg(h.plane);
                    const auto p = g.grabPoint(h);
                    QVERIFY2(p, qPrintable(what + QStringLiteral(" is drawn, nothing grabs it")));
                    const auto picked = g.handleAt(*p);
                    QVERIFY2(picked && *picked == h, qPrintable(what));
                    QVERIFY2(QRectF(frame).contains(*p), qPrintable(what));
                }
            // At least the arrows and boxes of two axes, a square and the three rings.
            QVERIFY2(shown >= 8, qPrintable(where + QStringLiteral(": %1 handles").arg(shown)));
        }
        // In the middle the gizmo keeps its full size: rings of kRingPx.
        const TransformGizmo middle(projection, Vec3(0.0f), Mat3(1.0f));
        QCOMPARE(middle.scale(), 1.0);
        // Straight on, the Z ring is a circle of that radius.
        if (eye.x == 0.0f) QVERIFY(middle.bounds().height() >= 2 * TransformGizmo::kRingPx);
    }
}

void UiLogicTest::sunGlyph_FromAFile_GoesUpstreamOfTheScene() {
    SceneDocument doc;
    Object ball;
    ball.geometry = SphereGeometry{Vec3(4.0f, 1.0f, 0.0f), 1.0f};  // bounds (3..5, 0..2, -1..1)
    doc.addObject(ball);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = Vec3(0.0f, -2.0f, 0.0f);  // straight down, any length
    const ObjectId read = doc.addLight(sun);
    sun.position = Vec3(7.0f, 7.0f, 7.0f);  // placed by the user in this run: kept
    const ObjectId placed = doc.addLight(sun);
    Light lamp;
    const ObjectId point = doc.addLight(lamp);  // a point light at the origin: not a sun
    anchorSunGlyphs(doc);
    // Bounds centre (4, 1, 0), radius half the diagonal, sqrt(12) / 2; the glyph goes up
    // (against the light) from the centre by that radius plus one unit.
    const Vec3 expected(4.0f, 1.0f + std::sqrt(3.0f) + 1.0f, 0.0f);
    QVERIFY(glm::length(doc.findLight(read)->position - expected) < 1e-5f);
    QCOMPARE(doc.findLight(placed)->position, Vec3(7.0f, 7.0f, 7.0f));
    QCOMPARE(doc.findLight(point)->position, Vec3(0.0f));
}

void UiLogicTest::duplicate_CountsOnFromTheCopysNumber() {
    SceneDocument doc;
    const ObjectId wall = addBall(doc, "right wall");
    const ObjectId wall2 = duplicate(doc, wall);
    QCOMPARE(nameOf(doc, wall2), std::string("right wall 2"));
    QCOMPARE(nameOf(doc, duplicate(doc, wall2)), std::string("right wall 3"));
    // Not "right wall 2 2", and not a number already taken.
    QCOMPARE(nameOf(doc, duplicate(doc, wall2)), std::string("right wall 4"));
    QCOMPARE(nameOf(doc, duplicate(doc, wall)), std::string("right wall 5"));

    // The copy of "ball 9" alone is "ball 10"; lights count the same way.
    const ObjectId ball9 = addBall(doc, "ball 9");
    QCOMPARE(nameOf(doc, duplicate(doc, ball9)), std::string("ball 10"));
    Light l;
    l.name = "key 2";
    const ObjectId key2 = doc.addLight(l);
    QCOMPARE(nameOf(doc, duplicate(doc, key2)), std::string("key 3"));
}

void UiLogicTest::duplicate_NamesWithoutAPlainNumberGetOneAppended() {
    SceneDocument doc;
    for (const char* name : {"sphere", "pi 3.14", "take 02", "room -1", "7"}) {
        const ObjectId id = addBall(doc, name);
        QCOMPARE(nameOf(doc, duplicate(doc, id)), std::string(name) + " 2");
    }
    QCOMPARE(uniqueName(doc, "fresh"), std::string("fresh"));
}

void UiLogicTest::defaultScene_BuildTree_FoundFromAnyExecutableFolder() {
    // No installed copy beside a temporary folder: the source tree the build came from.
    QTemporaryDir dir;
    const QString expected =
        QFileInfo(QStringLiteral(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json"))
            .canonicalFilePath();
    QVERIFY(!expected.isEmpty());
    QCOMPARE(defaultScenePath(dir.path()), expected);
    QCOMPARE(defaultScenePath(QCoreApplication::applicationDirPath()), expected);
}

void UiLogicTest::defaultScene_Installed_PrefersShareNextToTheExecutable() {
    QTemporaryDir prefix;
    QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("bin")));
    QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("share/raystudio/scenes")));
    const QString installed =
        prefix.filePath(QStringLiteral("share/raystudio/scenes/reference-room.scene.json"));
    QVERIFY(
        QFile::copy(QStringLiteral(RAYSTUDIO_SCENES_DIR "/reference-room.scene.json"), installed));
    QCOMPARE(defaultScenePath(prefix.filePath(QStringLiteral("bin"))),
             QFileInfo(installed).canonicalFilePath());
}

void UiLogicTest::displayAutomatic_PicksSoftwareOnSoftwareGL_OpenGLOnAGpu() {
    // GL_RENDERER strings as Mesa and the vendors' drivers report them.
    const QString llvmpipe = QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)");
    for (const char* software : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe",
                                 "Software Rasterizer", "Mesa DRI swrast"}) {
        QVERIFY2(softwareRenderer(QString::fromLatin1(software)), software);
        QVERIFY(!useOpenGL(DisplayKind::Automatic, QString::fromLatin1(software)));
    }
    for (const char* gpu :
         {"NVIDIA GeForce RTX 3060/PCIe/SSE2", "Mesa Intel(R) UHD Graphics 620 (KBL GT2)",
          "AMD Radeon RX 6600 (navi23, LLVM 15.0.6, DRM 3.49, 6.1.0-13-amd64)", "Apple M1"}) {
        QVERIFY2(!softwareRenderer(QString::fromLatin1(gpu)), gpu);
        QVERIFY2(useOpenGL(DisplayKind::Automatic, QString::fromLatin1(gpu)), gpu);
    }
    // The user's choice wins, except that OpenGL needs a context (no renderer: none).
    QVERIFY(useOpenGL(DisplayKind::OpenGL, llvmpipe));
    QVERIFY(!useOpenGL(DisplayKind::Software, QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2")));
    QVERIFY(!useOpenGL(DisplayKind::OpenGL, QString()));
    QVERIFY(!useOpenGL(DisplayKind::Automatic, QString()));
    // Stored by name; an unknown name is refused (loadPreferences falls back to Automatic).
    for (DisplayKind k : {DisplayKind::Automatic, DisplayKind::OpenGL, DisplayKind::Software}) {
        DisplayKind parsed = k == DisplayKind::OpenGL ? DisplayKind::Software : DisplayKind::OpenGL;
        QVERIFY(parseDisplayKind(QString::fromLatin1(displayKindName(k)), parsed));
        QCOMPARE(parsed, k);
    }
    DisplayKind untouched = DisplayKind::Software;
    QVERIFY(!parseDisplayKind(QStringLiteral("vulkan"), untouched));
    QCOMPARE(untouched, DisplayKind::Software);
}

namespace {

bool near(const Vec3& a, const Vec3& b) {
    return glm::length(a - b) < 1e-4f;
}

}  // namespace

void UiLogicTest::scaleAlongWorldX_StretchesTheAxisOfARotatedObjectThatLiesAlongX() {
    SceneDocument doc;
    const ObjectId ball = addBall(doc, "ball");
    doc.findObject(ball)->transform.rotate = Vec3(0.0f, 0.0f, 90.0f);  // local y lies along -x
    scaleAll(doc, {ball}, Vec3(0.0f), Vec3(2.0f, 1.0f, 1.0f));
    const Transform& t = doc.findObject(ball)->transform;
    // The world's x is the object's y: that is the axis that doubles.
    QVERIFY2(near(t.scale, Vec3(1.0f, 2.0f, 1.0f)),
             qPrintable(QString("%1 %2 %3").arg(t.scale.x).arg(t.scale.y).arg(t.scale.z)));
    QCOMPARE(t.rotate, Vec3(0.0f, 0.0f, 90.0f));
    // And its world matrix is the scale applied to the old one.
    const Mat4 expected = glm::scale(Mat4(1.0f), Vec3(2.0f, 1.0f, 1.0f)) *
                          Transform{Vec3(0.0f), Vec3(0.0f, 0.0f, 90.0f), Vec3(1.0f)}.matrix();
    const Mat4 got = t.matrix();
    for (int c = 0; c < 4; ++c) QVERIFY(near(Vec3(got[c]), Vec3(expected[c])));
}

void UiLogicTest::scaleAlongLocalAxes_MovesOtherObjectsAlongThoseAxes() {
    SceneDocument doc;
    const ObjectId a = addBall(doc, "a");
    const ObjectId b = addBall(doc, "b");
    doc.findObject(b)->transform.translate = Vec3(0.0f, 1.0f, 0.0f);
    // The gizmo's local axes turned 90 degrees about z: its x is the world's y.
    const Mat3 axes(Vec3(0.0f, 1.0f, 0.0f), Vec3(-1.0f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f));
    scaleAll(doc, {a, b}, Vec3(0.0f), Vec3(3.0f, 1.0f, 1.0f), axes);
    QVERIFY(near(doc.findObject(b)->transform.translate, Vec3(0.0f, 3.0f, 0.0f)));
    // Unrotated balls stretch along the world axis that the gizmo's x is.
    QVERIFY(near(doc.findObject(a)->transform.scale, Vec3(1.0f, 3.0f, 1.0f)));
    QVERIFY(near(doc.findObject(a)->transform.translate, Vec3(0.0f)));
}

void UiLogicTest::outlineShortcuts_AgreeWithOnOutlinePixelForPixel() {
    // Blobs of ids (and empty space) on a small frame: drawOutlineRow and reshading by
    // outlinedBounds skip pixels that are not at an id edge, and must not miss any.
    ui::DisplayFrame f;
    f.width = 37;
    f.height = 23;
    f.id.assign(std::size_t(f.width * f.height), kNoObject);
    uint32_t h = 12345u;
    for (int k = 0; k < 12; ++k) {
        h = h * 1664525u + 1013904223u;
        const int cx = int(h >> 8) % f.width, cy = int(h >> 16) % f.height,
                  r = 1 + int(h >> 24) % 6;
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x)
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r)
                    f.id[std::size_t(y * f.width + x)] = ObjectId(1 + k % 5);
    }
    for (const std::vector<ObjectId>& selected :
         {std::vector<ObjectId>{}, {1}, {3, 5}, {2, 9}, {kNoObject, 4}, {9}}) {
        int x0 = f.width, y0 = f.height, x1 = -1, y1 = -1;
        for (int y = 0; y < f.height; ++y) {
            std::vector<uint8_t> line(std::size_t(3 * f.width), 7);
            ui::drawOutlineRow(f, y, 0, f.width - 1, selected, line.data());
            for (int x = 0; x < f.width; ++x) {
                const bool on = ui::onOutline(f, x, y, selected);
                QCOMPARE(line[std::size_t(3 * x)] == ui::kOutlineRgb[0], on);
                if (on) QVERIFY(ui::atIdEdge(f, x, y));
                if (ui::outlined(selected, f.idAt(x, y)))
                    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = y;
            }
        }
        const QRect expected = x1 < 0 ? QRect() : QRect(QPoint(x0, y0), QPoint(x1, y1));
        QCOMPARE(ui::outlinedBounds(f, selected, {}), expected);
        QCOMPARE(ui::outlinedBounds(f, {}, selected), expected);
    }
    QCOMPARE(ui::outlinedBounds(f, {1}, {3}),
             ui::outlinedBounds(f, {1}, {}).united(ui::outlinedBounds(f, {3}, {})));
}

void UiLogicTest::dialogFolders_OpenWhereTheUserLastChose_PerKindOfFile() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("RayStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("RayStudioDialogFolders"));
    QSettings().clear();
    QTemporaryDir root;
    QVERIFY(root.isValid());
    const QString scenes = root.filePath(QStringLiteral("scenes"));
    const QString meshes = root.filePath(QStringLiteral("meshes"));
    QVERIFY(QDir().mkpath(scenes) && QDir().mkpath(meshes));
    const QString document = scenes + QStringLiteral("/room.scene.json");

    // Nothing chosen yet: the open document's folder, else home.
    QCOMPARE(ui::dialogFolder(ui::FileKind::Mesh, document), scenes);
    QCOMPARE(ui::dialogFolder(ui::FileKind::Mesh, {}), QDir::homePath());
    // A mesh picked elsewhere: mesh dialogs open there, scene dialogs do not.
    ui::rememberDialogFolder(ui::FileKind::Mesh, meshes + QStringLiteral("/bunny.ply"));
    QCOMPARE(ui::dialogFolder(ui::FileKind::Mesh, document), meshes);
    QCOMPARE(ui::dialogFolder(ui::FileKind::Scene, document), scenes);
    // A cancelled dialog (empty path) forgets nothing; a folder since deleted is passed over.
    ui::rememberDialogFolder(ui::FileKind::Mesh, {});
    QCOMPARE(ui::dialogFolder(ui::FileKind::Mesh, document), meshes);
    QVERIFY(QDir(meshes).removeRecursively());
    QCOMPARE(ui::dialogFolder(ui::FileKind::Mesh, document), scenes);
    QSettings().clear();
}

QTEST_GUILESS_MAIN(UiLogicTest)
#include "ui_logic_test.moc"
