// Editing like a 3D tool, with real events: a view camera apart from the scene camera,
// G / R / S gestures with axis locks and typed values, and lights as pickable glyphs.
#include <QAction>
#include <QApplication>
#include <QCursor>
#include <QStatusBar>
#include <QWheelEvent>
#include <QtTest>
#include <cmath>

#include "document/transform_edits.h"
#include "drag_geometry.h"
#include "gui_test_support.h"
#include "panels/outliner_model.h"
#include "panels/outliner_view.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

QAction* actionNamed(const QWidget& window, const QString& text) {
    for (QAction* a : window.findChildren<QAction*>())
        if (a->iconText() == text) return a;
    return nullptr;
}

bool near(const Vec3& a, const Vec3& b, float tol = 1e-4f) {
    return glm::length(a - b) <= tol;
}

/// True when `p` lies inside every plane of `doc` (the room's walls face inwards).
bool insideWalls(const SceneDocument& doc, const Vec3& p, QString* which) {
    for (const Object& o : doc.objects) {
        const auto* plane = std::get_if<PlaneGeometry>(&o.geometry);
        if (plane && glm::dot(p - plane->point, plane->normal) <= 0.0f) {
            *which = QString::fromStdString(o.name);
            return false;
        }
    }
    return true;
}

/// The view's axes as the columns of a rotation: right, true up and forward.
Mat3 viewAxes(const Camera& c) {
    const Vec3 forward = glm::normalize(c.target - c.position);
    const Vec3 right = glm::normalize(glm::cross(forward, c.up));
    return Mat3(right, glm::cross(right, forward), forward);
}

}  // namespace

class EditingTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void orbitPanDolly_MoveTheViewOnly_DocumentUnmodifiedAndUndoEmpty();
    void orbit_TurnsAboutTheSelectionsCentre();
    void sceneCameraFromView_IsOneUndoStep_AndThroughSceneCameraFollowsIt();
    void axisViews_LookAlongTheWorldAxes();
    void frameSelection_InTheReferenceRoom_KeepsTheViewInsideTheWalls();
    void wheel_DollyStopsShortOfTheWalls_AndStepsByWhatIsUnderTheCursor();
    void rotateZ45Enter_RotatesByFortyFiveDegrees_InOneUndoStep();
    void scale2Enter_DoublesTheScale_InPlace();
    void moveX1Enter_MovesByOneAlongX();
    void freeMove_TheStatusBarShowsTheDistanceMoved();
    void escape_RestoresTheSelection_AndLeavesNoUndoStep();
    void ctrlWhileMoving_SnapsToTheGrid();
    void lightGlyph_IsPickedByClicking_AndMovesWithG();
    void lightSelectedInOutliner_IsHighlighted();

private:
    Viewport* viewport() { return window_->viewport(); }
    const SceneDocument& doc() { return window_->editor()->document(); }
    /// Clicks `name` in the viewport (a real press and release on its pixels).
    void clickObject(const std::string& name);

    std::unique_ptr<MainWindow> window_;
};

void EditingTest::init() {
    QVERIFY(openRoomWindow(window_));
    viewport()->setFocus();
}

void EditingTest::cleanup() {
    if (!window_) return;
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

void EditingTest::clickObject(const std::string& name) {
    const ObjectId id = idOf(*window_, name);
    const auto [x, y] = pixelOf(*viewport()->frame(), id);
    QVERIFY2(x >= 0, name.c_str());
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, viewport()->widgetPointOf(x, y));
    QCOMPARE(window_->editor()->selection(), id);
}

void EditingTest::orbitPanDolly_MoveTheViewOnly_DocumentUnmodifiedAndUndoEmpty() {
    Viewport* v = viewport();
    const SceneDocument before = doc();
    QVERIFY(v->throughSceneCamera());
    QVERIFY(v->viewCamera() == before.camera);
    const QPoint c = v->rect().center();

    QTest::mousePress(v, Qt::RightButton, {}, c);  // Orbit.
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(v, c + QPoint(6 * i, 2 * i));
    QTest::mouseRelease(v, Qt::RightButton, {}, c + QPoint(30, 10));
    const Camera orbited = v->viewCamera();
    QVERIFY(!(orbited == before.camera));

    QTest::mousePress(v, Qt::MiddleButton, {}, c);  // Pan.
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(v, c + QPoint(-5 * i, 3 * i));
    QTest::mouseRelease(v, Qt::MiddleButton, {}, c + QPoint(-25, 15));
    const Camera panned = v->viewCamera();
    QVERIFY(!(panned == orbited));

    QWheelEvent wheel(c, v->mapToGlobal(c), QPoint(), QPoint(0, 240), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(v, &wheel);  // Dolly.
    QVERIFY(!(v->viewCamera() == panned));
    QVERIFY(!v->throughSceneCamera());

    QVERIFY(doc().sameContent(before));
    QVERIFY(doc().camera == before.camera);
    QCOMPARE(window_->editor()->undoStack()->count(), 0);
    QVERIFY(window_->editor()->undoStack()->isClean());
    QVERIFY(!window_->isWindowModified());

    // The session renders through the view camera.
    QVERIFY(settle(*window_));
    const auto snapshot = renderSession(*window_).snapshot();
    QVERIFY(near(snapshot->camera().origin(), v->viewCamera().position));
}

// A turntable turn at 0.4 degrees a pixel: 25 pixels to the right turn the heading 10 degrees
// (about the vertical, the view swinging to the right), 10 pixels down tip the view 4 degrees
// lower; and the turn is rigid about the ball, so the camera's offset from it turns exactly as
// its axes do.
void EditingTest::orbit_TurnsAboutTheSelectionsCentre() {
    clickObject("blue ball");
    const Vec3 centre = *entityCentre(doc(), idOf(*window_, "blue ball"));
    Viewport* v = viewport();
    const auto distanceTo = [&](const Vec3& p) {
        return glm::length(v->viewCamera().position - p);
    };
    const float before = distanceTo(centre);
    const Camera start = v->viewCamera();
    const QPoint c = v->rect().center();
    // A turn small enough that no wall comes between the ball and the view (a larger one is
    // clipped: orbitAboutAFarWall_KeepsTheViewInsideTheRoom).
    QTest::mousePress(v, Qt::RightButton, {}, c);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(v, c + QPoint(5 * i, 2 * i));
    QTest::mouseRelease(v, Qt::RightButton, {}, c + QPoint(25, 10));
    // A rigid turn about the ball: the view keeps its distance to it, not to a point 8.5 away.
    QVERIFY2(std::abs(distanceTo(centre) - before) < 1e-3f,
             qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(distanceTo(centre))));
    const Camera turned = v->viewCamera();
    const auto heading = [](const Camera& c) {
        const Vec3 f = glm::normalize(c.target - c.position);
        return glm::degrees(std::atan2(f.x, -f.z));
    };
    const auto elevation = [](const Camera& c) {
        return glm::degrees(std::asin(glm::normalize(c.target - c.position).y));
    };
    const float yaw = std::remainder(heading(turned) - heading(start), 360.0f);
    const float pitch = elevation(turned) - elevation(start);
    QVERIFY2(std::abs(yaw - 10.0f) < 0.05f && std::abs(pitch + 4.0f) < 0.05f,
             qPrintable(QStringLiteral("yaw %1, pitch %2").arg(yaw).arg(pitch)));
    const Vec3 expected =
        centre + viewAxes(turned) * glm::transpose(viewAxes(start)) * (start.position - centre);
    QVERIFY2(glm::length(turned.position - expected) < 1e-3f,
             qPrintable(str(turned.position) + QStringLiteral(", expected ") + str(expected)));
}

void EditingTest::sceneCameraFromView_IsOneUndoStep_AndThroughSceneCameraFollowsIt() {
    Viewport* v = viewport();
    const Camera scene = doc().camera;
    const QPoint c = v->rect().center();
    QTest::mousePress(v, Qt::RightButton, {}, c);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(v, c + QPoint(8 * i, 0));
    QTest::mouseRelease(v, Qt::RightButton, {}, c + QPoint(40, 0));
    const Camera view = v->viewCamera();

    QAction* fromView = actionNamed(*window_, QStringLiteral("Scene Camera from View"));
    QVERIFY(fromView);
    fromView->trigger();
    QCOMPARE(window_->editor()->undoStack()->count(), 1);
    QVERIFY(near(doc().camera.position, view.position));
    QVERIFY(near(doc().camera.target, view.target));
    QVERIFY(window_->isWindowModified());
    QVERIFY(v->throughSceneCamera());

    window_->editor()->undoStack()->undo();
    QVERIFY(doc().camera == scene);
    QVERIFY(v->viewCamera() == scene);  // Looking through it, the view follows the undo.

    // Key 0 (Numpad 0): back through the scene camera after navigating away.
    QTest::mousePress(v, Qt::RightButton, {}, c);
    QTest::mouseMove(v, c + QPoint(0, 20));
    QTest::mouseRelease(v, Qt::RightButton, {}, c + QPoint(0, 20));
    QVERIFY(!(v->viewCamera() == scene));
    QTest::keyClick(v, Qt::Key_0);
    QVERIFY(v->viewCamera() == scene);
    QVERIFY(v->throughSceneCamera());
}

void EditingTest::axisViews_LookAlongTheWorldAxes() {
    Viewport* v = viewport();
    const struct {
        Qt::Key key;
        Qt::KeyboardModifiers mods;
        Vec3 forward;
    } views[] = {{Qt::Key_1, {}, {0, 0, -1}}, {Qt::Key_1, Qt::ControlModifier, {0, 0, 1}},
                 {Qt::Key_3, {}, {-1, 0, 0}}, {Qt::Key_3, Qt::ControlModifier, {1, 0, 0}},
                 {Qt::Key_7, {}, {0, -1, 0}}, {Qt::Key_7, Qt::ControlModifier, {0, 1, 0}}};
    const float distance = glm::length(doc().camera.target - doc().camera.position);
    for (const auto& view : views) {
        QTest::keyClick(v, view.key, view.mods);
        const Camera& c = v->viewCamera();
        QVERIFY2(near(glm::normalize(c.target - c.position), view.forward),
                 qPrintable(str(c.position)));
        QVERIFY(std::abs(glm::length(c.target - c.position) - distance) < 1e-3f);
    }
    // Top view: X to the right, as in Blender.
    QTest::keyClick(v, Qt::Key_7);
    const CameraModel top(v->viewCamera(), 160, 90);
    QVERIFY(near(top.right(), Vec3(1, 0, 0)));
    QCOMPARE(window_->editor()->undoStack()->count(), 0);
}

void EditingTest::frameSelection_InTheReferenceRoom_KeepsTheViewInsideTheWalls() {
    // Framed from behind, from a side or from below, these balls sit closer to a wall than
    // the framing distance: unclipped, the view would stand outside the room.
    const struct {
        const char* ball;
        Qt::Key key;
        Qt::KeyboardModifiers mods;
    } cases[] = {{"green ball", Qt::Key_1, Qt::ControlModifier},
                 {"green ball", Qt::Key_3, {}},
                 {"mirror ball", Qt::Key_3, Qt::ControlModifier},
                 {"mirror ball", Qt::Key_1, Qt::ControlModifier},
                 {"mirror ball", Qt::Key_7, Qt::ControlModifier}};
    const SceneDocument before = doc();
    Viewport* v = viewport();
    for (const auto& k : cases) {
        const ObjectId id = idOf(*window_, k.ball);
        window_->editor()->setSelection(id);
        QTest::keyClick(v, k.key, k.mods);
        QTest::keyClick(v, Qt::Key_F);
        const Camera& c = v->viewCamera();
        const Vec3 centre = *entityCentre(doc(), id);
        QVERIFY(near(c.target, centre));
        const float radius = std::get<SphereGeometry>(doc().findObject(id)->geometry).radius;
        const float unclipped = radius / std::sin(glm::radians(c.fovY) * 0.5f) * 1.2f;
        QString wall;
        QVERIFY2(insideWalls(doc(), c.position, &wall),
                 qPrintable(QString::fromLatin1(k.ball) + " view at " + str(c.position) +
                            " is behind " + wall));
        QVERIFY2(glm::length(c.position - centre) < unclipped, k.ball);  // It was clipped.
    }
    QVERIFY(doc().sameContent(before));
    QCOMPARE(window_->editor()->undoStack()->count(), 0);
}

void EditingTest::wheel_DollyStopsShortOfTheWalls_AndStepsByWhatIsUnderTheCursor() {
    Viewport* v = viewport();
    auto wheel = [&](int clicks, const QPoint& at) {
        for (int i = 0; i < std::abs(clicks); ++i) {
            QWheelEvent e(at, v->mapToGlobal(at), QPoint(), QPoint(0, clicks > 0 ? 120 : -120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(v, &e);
        }
    };
    const QPoint centre = v->rect().center();
    QString wall;
    // Out, far more than the room is deep: the view stays inside, short of the front wall.
    const Vec3 start = v->viewCamera().position;
    wheel(-40, centre);
    QVERIFY2(insideWalls(doc(), v->viewCamera().position, &wall),
             qPrintable("out: behind " + wall + " at " + str(v->viewCamera().position)));
    QVERIFY(glm::length(v->viewCamera().position - start) > 0.1f);  // It did move out.
    // In, far more than the room is deep: short of the back wall.
    wheel(60, centre);
    QVERIFY2(insideWalls(doc(), v->viewCamera().position, &wall),
             qPrintable("in: behind " + wall + " at " + str(v->viewCamera().position)));

    // One click in over a ball moves a tenth of the way to its surface; over the back wall,
    // a tenth of the way to the wall: further.
    const ObjectId ball = idOf(*window_, "orange ball");
    v->viewThroughSceneCamera();
    QVERIFY(settle(*window_));
    const auto [bx, by] = pixelOf(*v->frame(), ball);
    const Vec3 eye = v->viewCamera().position;
    wheel(1, v->widgetPointOf(bx, by));
    const float towardBall = glm::length(v->viewCamera().position - eye);
    // The surface under the cursor is nearer than the ball's centre.
    const float toSurfaceAtMost = glm::length(*entityCentre(doc(), ball) - eye);
    QVERIFY(towardBall > 0.0f);
    QVERIFY2(towardBall <= 0.1f * toSurfaceAtMost + 1e-4f, qPrintable(QString::number(towardBall)));
    v->viewThroughSceneCamera();
    QVERIFY(settle(*window_));
    const auto [wx, wy] = pixelOf(*v->frame(), idOf(*window_, "back wall"));
    wheel(1, v->widgetPointOf(wx, wy));
    const float towardWall = glm::length(v->viewCamera().position - eye);
    QVERIFY2(towardWall > towardBall,
             qPrintable(QString::number(towardWall) + " vs " + QString::number(towardBall)));
}

void EditingTest::rotateZ45Enter_RotatesByFortyFiveDegrees_InOneUndoStep() {
    clickObject("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    const SceneDocument before = doc();
    QTest::keyClicks(viewport(), QStringLiteral("rz45"));
    QVERIFY(viewport()->transforming());
    QTest::keyClick(viewport(), Qt::Key_Return);
    QVERIFY(!viewport()->transforming());
    const Transform& t = doc().findObject(id)->transform;
    QVERIFY2(near(t.rotate, Vec3(0, 0, 45)), qPrintable(str(t.rotate)));
    // About the ball's own centre: it stays where it was.
    QVERIFY(near(*entityCentre(doc(), id), *entityCentre(before, id)));
    QCOMPARE(window_->editor()->undoStack()->count(), 1);
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().sameContent(before));
}

void EditingTest::scale2Enter_DoublesTheScale_InPlace() {
    clickObject("glass ball");
    const ObjectId id = idOf(*window_, "glass ball");
    const Vec3 centre = *entityCentre(doc(), id);
    QTest::keyClicks(viewport(), QStringLiteral("s2"));
    QTest::keyClick(viewport(), Qt::Key_Enter);
    QVERIFY(near(doc().findObject(id)->transform.scale, Vec3(2.0f)));
    QVERIFY(near(*entityCentre(doc(), id), centre));
    QCOMPARE(window_->editor()->undoStack()->count(), 1);
    // The session sees the bigger ball.
    QVERIFY(settle(*window_));
    const Aabb b = renderSession(*window_).snapshot()->objectBounds(id);
    QVERIFY(std::abs(b.extent().x - 4.0f) < 1e-3f);
}

void EditingTest::moveX1Enter_MovesByOneAlongX() {
    clickObject("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    const Vec3 before = doc().findObject(id)->transform.translate;
    QTest::keyClicks(viewport(), QStringLiteral("gx1"));
    QTest::keyClick(viewport(), Qt::Key_Return);
    QVERIFY(near(doc().findObject(id)->transform.translate, before + Vec3(1, 0, 0)));
    QCOMPARE(window_->editor()->undoStack()->count(), 1);

    // Typed values can be negative and fractional, and Backspace takes back a digit.
    QTest::keyClicks(viewport(), QStringLiteral("gy-0.59"));
    QTest::keyClick(viewport(), Qt::Key_Backspace);
    QTest::keyClick(viewport(), Qt::Key_Return);
    QVERIFY2(near(doc().findObject(id)->transform.translate, before + Vec3(1, -0.5f, 0)),
             qPrintable(str(doc().findObject(id)->transform.translate)));
    QCOMPARE(window_->editor()->undoStack()->count(), 2);
}

void EditingTest::freeMove_TheStatusBarShowsTheDistanceMoved() {
    clickObject("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    const Vec3 before = doc().findObject(id)->transform.translate;
    Viewport* v = viewport();
    const QPoint start = v->rect().center();
    QTest::mouseMove(v, start);
    QTest::keyClick(v, Qt::Key_G);
    QTest::mouseMove(v, start + QPoint(40, -10));
    const Vec3 d = doc().findObject(id)->transform.translate - before;
    QVERIFY(glm::length(d) > 0.01f);
    // Blender's header: the move along each axis and its length, as the document has it.
    const QString shown = window_->statusBar()->currentMessage();
    const QString expected = QStringLiteral("D %1 %2 %3 (%4)")
                                 .arg(double(d.x), 0, 'f', 3)
                                 .arg(double(d.y), 0, 'f', 3)
                                 .arg(double(d.z), 0, 'f', 3)
                                 .arg(double(glm::length(d)), 0, 'f', 3);
    QVERIFY2(shown.startsWith(QStringLiteral("Move")) && shown.contains(expected),
             qPrintable(shown + " / " + expected));
    QTest::keyClick(v, Qt::Key_Escape);
}

void EditingTest::escape_RestoresTheSelection_AndLeavesNoUndoStep() {
    clickObject("blue ball");
    const SceneDocument before = doc();
    Viewport* v = viewport();
    const QPoint c = v->rect().center();
    QTest::mouseMove(v, c);
    QTest::keyClick(v, Qt::Key_G);
    QVERIFY(v->transforming());
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(v, c + QPoint(10 * i, -4 * i));
    QVERIFY(!doc().sameContent(before));  // The gesture shows as it goes.
    QTest::keyClick(v, Qt::Key_Escape);
    QVERIFY(!v->transforming());
    QVERIFY(doc().sameContent(before));
    QVERIFY(!window_->editor()->undoStack()->canUndo());

    // The same for typed rotation and scale.
    QTest::keyClicks(v, QStringLiteral("rx30"));
    QTest::keyClick(v, Qt::Key_Escape);
    QTest::keyClicks(v, QStringLiteral("s3"));
    QTest::keyClick(v, Qt::Key_Escape);
    QVERIFY(doc().sameContent(before));
    QVERIFY(!window_->editor()->undoStack()->canUndo());
}

// G X carries the ball along X as far as the cursor goes along the image of the X axis through
// it (alongAxis, within 2 %: the cursor stands on whole pixels, up to half a pixel off that
// line); with Ctrl held, that distance rounded to the nearest multiple of the 0.25 grid step.
// The drag ends an odd number of steps away, where a grid of another step would not land.
void EditingTest::ctrlWhileMoving_SnapsToTheGrid() {
    clickObject("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    const Vec3 before = doc().findObject(id)->transform.translate;
    const Vec3 centre = *entityCentre(doc(), id);
    const Vec3 x(1, 0, 0);
    Viewport* v = viewport();
    const ViewProjection view = v->projection();
    const QPoint c = view.project(centre)->toPoint();
    const QPointF e = screenDirection(view, centre, x);
    const auto along = [&](double pixels) { return c + (pixels * e).toPoint(); };
    // G measures from QCursor::pos(). Under xcb QTest::mouseMove warps the real pointer
    // asynchronously, to where the window was when it asked (a window still being placed
    // moves after): the move started elsewhere. Warp until the viewport sees the pointer at c.
    const auto pointerAt = [v](QPoint p) {
        QTest::mouseMove(v, p);
        return v->mapFromGlobal(QCursor::pos()) == p;
    };
    QTRY_VERIFY(pointerAt(c));
    QTest::keyClicks(v, QStringLiteral("gx"));
    for (int i = 1; i <= 6; ++i) QTest::mouseMove(v, along(12.0 * i));
    // The warps' own motion events may come after the test's: let them arrive, then move
    // once more to where the test reads the ball.
    QTRY_VERIFY(pointerAt(along(72.0)));
    QTest::qWait(20);
    QTest::mouseMove(v, along(72.0));
    const double free = alongAxis(view, centre, x, c, along(72.0));
    const Vec3 followed = doc().findObject(id)->transform.translate - before;
    QVERIFY2(free > 0.3 && std::abs(followed.x - free) <= 0.02 * free && followed.y == 0.0f &&
                 followed.z == 0.0f,
             qPrintable(str(followed) + QStringLiteral(", expected x %1").arg(free)));
    const QPointF end(along(78.0));
    QMouseEvent move(QEvent::MouseMove, end, v->mapToGlobal(end), Qt::NoButton, Qt::NoButton,
                     Qt::ControlModifier);
    QApplication::sendEvent(v, &move);
    QTest::mouseClick(v, Qt::LeftButton, {}, end.toPoint());  // A click confirms.
    QVERIFY(!v->transforming());
    const Vec3 delta = doc().findObject(id)->transform.translate - before;
    const double steps = alongAxis(view, centre, x, c, end) / 0.25;
    // Not so near half a step that the whole pixels could round it either way (they stay
    // within 0.01 steps of alongAxis), and an odd number of steps.
    QVERIFY2(std::abs(steps - std::floor(steps) - 0.5) > 0.1 && int(std::round(steps)) % 2 == 1,
             qPrintable(QString::number(steps)));
    const double snapped = 0.25 * std::round(steps);
    QVERIFY2(snapped > 0.0 && std::abs(delta.x - snapped) < 1e-5,
             qPrintable(str(delta) + QStringLiteral(", expected x %1").arg(snapped)));
    QCOMPARE(delta.y, 0.0f);
    QCOMPARE(delta.z, 0.0f);
    QCOMPARE(window_->editor()->undoStack()->count(), 1);
}

void EditingTest::lightGlyph_IsPickedByClicking_AndMovesWithG() {
    const Light& light = doc().lights.front();
    const ObjectId id = light.id;
    const Vec3 before = light.position;
    const auto glyphs = viewport()->lightGlyphs();
    QCOMPARE(int(glyphs.size()), 1);
    const QPoint at = glyphs.front().centre.toPoint();
    // The ceiling is behind the glyph in the id buffer; the light wins.
    QVERIFY(viewport()->pixelAt(at));
    QTest::mouseClick(viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(window_->editor()->selection(), id);
    QTest::keyClicks(viewport(), QStringLiteral("gx1"));
    QTest::keyClick(viewport(), Qt::Key_Return);
    QVERIFY(near(doc().findLight(id)->position, before + Vec3(1, 0, 0)));
    QCOMPARE(window_->editor()->undoStack()->count(), 1);
    // The glyph followed it to the right.
    QVERIFY(viewport()->lightGlyphs().front().centre.x() > at.x() + 5);

    // The mouse drag moves it too, in the plane through it parallel to the image, as far as
    // the drag's 30 pixels down span at its depth (acrossView, exact but for rounding).
    const Vec3 dragged = doc().findLight(id)->position;
    QCOMPARE(viewport()->projection().imageRect(), viewport()->rect());  // the image fills it
    const Vec3 expected =
        acrossView(viewport()->viewCamera(), viewport()->height(), dragged, QPointF(0, 30));
    const QPoint from = viewport()->lightGlyphs().front().centre.toPoint();
    QTest::mousePress(viewport(), Qt::LeftButton, {}, from);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(viewport(), from + QPoint(0, 6 * i));
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, from + QPoint(0, 30));
    const Vec3 moved = doc().findLight(id)->position - dragged;
    QVERIFY2(expected.y < -0.1f && glm::length(moved - expected) <= 1e-3f * glm::length(expected),
             qPrintable(str(moved) + QStringLiteral(", expected ") + str(expected)));
    QCOMPARE(window_->editor()->undoStack()->count(), 2);
}

void EditingTest::lightSelectedInOutliner_IsHighlighted() {
    const ObjectId id = doc().lights.front().id;
    QVERIFY(settle(*window_));
    QTest::qWait(50);  // the OpenGL view has drawn its first frame
    const auto highlighted = [&] {
        // The OpenGL view paints the glyphs into its own framebuffer; the raster view's glyphs
        // are a widget over it.
        FrameView* view = viewport()->frameView();
        const QImage shown = (view->usesOpenGL() ? view->grabImage() : viewport()->grab().toImage())
                                 .convertToFormat(QImage::Format_RGB888);
        const QPoint c = viewport()->lightGlyphs().front().centre.toPoint();
        for (int y = c.y() - 10; y <= c.y() + 10; ++y)
            for (int x = c.x() - 10; x <= c.x() + 10; ++x) {
                // Near the outline colour: OpenGL's antialiased pen blends its edges.
                const QColor c = shown.pixelColor(x, y);
                if (std::abs(c.red() - kOutlineRgb[0]) <= 24 &&
                    std::abs(c.green() - kOutlineRgb[1]) <= 24 &&
                    std::abs(c.blue() - kOutlineRgb[2]) <= 24)
                    return true;
            }
        return false;
    };
    QVERIFY(!highlighted());
    window_->outliner()->setCurrentIndex(window_->outliner()->indexOf(id));
    QCOMPARE(window_->editor()->selection(), id);
    QTRY_VERIFY_WITH_TIMEOUT(highlighted(), 2000);  // the OpenGL view repaints asynchronously
}

QTEST_MAIN(EditingTest)
#include "editing_test.moc"
