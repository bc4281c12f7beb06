// The transform gizmo and multi-selection, with real mouse and key events (offscreen): the
// gizmo's scale boxes, rings and arrows, world and local axes, Ctrl/Shift-click, box select,
// Delete of a group, undo in the middle of a gesture, and orbiting about a far wall.
#include <QApplication>
#include <QLabel>
#include <QtTest>
#include <cmath>

#include "document/transform_edits.h"
#include "drag_geometry.h"
#include "gui_test_support.h"
#include "panels/outliner_model.h"
#include "panels/outliner_view.h"
#include "panels/property_panel.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

/// A left-button move with `mods` held (QTest::mouseMove sends no modifiers).
void moveHeld(QWidget* w, const QPointF& to, Qt::KeyboardModifiers mods = {}) {
    QMouseEvent e(QEvent::MouseMove, to, w->mapToGlobal(to), Qt::NoButton, Qt::LeftButton, mods);
    QApplication::sendEvent(w, &e);
}

/// Presses at `from`, moves in steps to `to` and releases there.
void drag(QWidget* w, const QPointF& from, const QPointF& to, Qt::KeyboardModifiers mods = {}) {
    QTest::mousePress(w, Qt::LeftButton, {}, from.toPoint());
    for (int i = 1; i <= 8; ++i) moveHeld(w, from + (to - from) * (i / 8.0), mods);
    QTest::mouseRelease(w, Qt::LeftButton, mods, to.toPoint());
}

}  // namespace

class GizmoTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void scaleBox_DraggedOutwards_ScalesAlongItsAxis_InOneUndoStep();
    void zRing_DraggedWithCtrl_RotatesAboutZ_In15DegreeSteps();
    void xArrow_MovesAlongX_AndInLocalAxesAlongTheObjectsOwnX();
    void planeSquare_MovesInItsPlaneOnly();
    void ctrlAndShiftClick_SelectSeveral_GMovesAll_OneUndoStep();
    void gizmoArrow_MovesTheWholeGroup();
    void boxSelect_SelectsTheBallsWhoseCentresAreInside();
    void delete_OfAGroup_IsOneUndoStep();
    void duplicate_OfAGroup_SelectsTheCopies();
    void outliner_CtrlClick_SelectsSeveral_AndFollowsTheViewport();
    void propertyPanel_WithSeveralSelected_SaysWhichOneItShows();
    void ctrlZ_DuringAGizmoDrag_CancelsIt_AndUndoesNothingElse();
    void ctrlZ_DuringAKeyGesture_CancelsIt();
    void undoFromTheMenu_DuringADrag_EndsTheDrag();
    void orbitAboutAFarWall_KeepsTheViewInsideTheRoom();
    void aLightSelectedFirst_ShowsAFullSizeGizmo();
    void nearTheTopEdge_TheGizmoStaysWhole_AndItsRingAndArrowWork();

private:
    Viewport* viewport() { return window_->viewport(); }
    SceneEditor* editor() { return window_->editor(); }
    const SceneDocument& doc() { return window_->editor()->document(); }
    const Object& object(const std::string& name) {
        return *doc().findObject(idOf(*window_, name));
    }
    /// Clicks `name` in the viewport with `mods`.
    void click(const std::string& name, Qt::KeyboardModifiers mods = {});
    /// The widget point grabbing `h` of the gizmo shown now (checked to grab exactly `h`).
    QPointF grab(const GizmoHandle& h);

    std::unique_ptr<MainWindow> window_;
};

void GizmoTest::init() {
    QVERIFY(openRoomWindow(window_));
    viewport()->setFocus();
}

void GizmoTest::cleanup() {
    if (!window_) return;
    editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

void GizmoTest::aLightSelectedFirst_ShowsAFullSizeGizmo() {
    // The first thing selected is a light, from the outliner (no object was selected before).
    QVERIFY(!doc().lights.empty());
    const ObjectId light = doc().lights.front().id;
    editor()->setSelection(light);
    const auto g = viewport()->gizmo();
    QVERIFY(g);
    // Its rings are kRingPx across on screen, whatever the light's distance (less near the
    // view's edge, down to kMinScale of that): the gizmo spans their diameter at the least,
    // not a few pixels.
    const QRectF b = g->bounds();
    QVERIFY2(
        std::max(b.width(), b.height()) > 2 * TransformGizmo::kRingPx * TransformGizmo::kMinScale,
        qPrintable(QStringLiteral("%1 x %2").arg(b.width()).arg(b.height())));
}

void GizmoTest::nearTheTopEdge_TheGizmoStaysWhole_AndItsRingAndArrowWork() {
    click("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    // The ball moved, at the same distance from the eye, to where its centre shows 40 pixels
    // below the viewport's top edge.
    {
        const ViewProjection view = viewport()->projection();
        const Vec3 centre = *entityCentre(doc(), id);
        const QPointF shown = *view.project(centre);
        const Ray ray = view.rayThrough(QPointF(shown.x(), 40.0));
        const Vec3 to = ray.origin + glm::normalize(ray.dir) * glm::length(centre - ray.origin);
        SceneDocument d = doc();
        d.findObject(id)->transform.translate += to - centre;
        editor()->edit(QStringLiteral("Move up"), std::move(d));
        QVERIFY(settle(*window_));
    }
    const Vec3 centre = *entityCentre(doc(), id);
    const QPointF pivot = *viewport()->projection().project(centre);
    QVERIFY2(std::abs(pivot.y() - 40.0) < 0.5, qPrintable(QString::number(pivot.y())));
    const auto g = viewport()->gizmo();
    QVERIFY(g);
    const QRectF b = g->bounds();
    QVERIFY2(QRectF(viewport()->rect()).contains(b),
             qPrintable(QStringLiteral("the gizmo reaches (%1, %2)-(%3, %4)")
                            .arg(b.left())
                            .arg(b.top())
                            .arg(b.right())
                            .arg(b.bottom())));

    // Its Z ring turns the ball about Z alone.
    const Transform before = object("blue ball").transform;
    const QPointF at = grab({TransformKind::Rotate, 2, false});
    QVERIFY(!at.isNull());
    const QPointF r = at - pivot;
    QTest::mousePress(viewport(), Qt::LeftButton, {}, at.toPoint());
    for (int i = 1; i <= 10; ++i) {
        const double a = -M_PI / 4 * i / 10.0;
        moveHeld(viewport(), pivot + QPointF(r.x() * std::cos(a) - r.y() * std::sin(a),
                                             r.x() * std::sin(a) + r.y() * std::cos(a)));
    }
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, viewport()->mapFromGlobal(QCursor::pos()));
    const Transform turned = object("blue ball").transform;
    QVERIFY2(std::abs(turned.rotate.z - before.rotate.z) > 20.0f, qPrintable(str(turned.rotate)));
    QCOMPARE(turned.rotate.x, before.rotate.x);
    QCOMPARE(turned.rotate.y, before.rotate.y);

    // Its X arrow moves the ball along X alone, by what the drag spans along X (within 2 %).
    const ViewProjection view = viewport()->projection();
    const QPointF from = QPointF(grab({TransformKind::Move, 0, false}).toPoint());
    QVERIFY(!from.isNull());
    const QPointF to = from + 30.0 * screenDirection(view, centre, Vec3(1, 0, 0));
    drag(viewport(), from, to);
    const Vec3 delta = object("blue ball").transform.translate - turned.translate;
    const double expected = alongAxis(view, centre, Vec3(1, 0, 0), from, to);
    QVERIFY2(expected > 0.05 && std::abs(delta.x - expected) <= 0.02 * expected &&
                 delta.y == 0.0f && delta.z == 0.0f,
             qPrintable(str(delta) + QStringLiteral(", expected x %1").arg(expected)));
    QCOMPARE(editor()->undoStack()->count(), 3);  // The move up, the turn, the move.
}

void GizmoTest::click(const std::string& name, Qt::KeyboardModifiers mods) {
    // The pixel of it nearest its middle that no handle of the gizmo shown now covers (a
    // click there would grab the handle, as in Blender).
    const DisplayFrame& f = *viewport()->frame();
    const ObjectId id = idOf(*window_, name);
    const auto [cx, cy] = pixelOf(f, id);
    QVERIFY2(cx >= 0, name.c_str());
    const auto gizmo = viewport()->gizmo();
    QPoint at(-1, -1);
    long best = -1;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            const long d = long(x - cx) * (x - cx) + long(y - cy) * (y - cy);
            if (f.idAt(x, y) != id || (best >= 0 && d >= best)) continue;
            const QPoint p = viewport()->widgetPointOf(x, y);
            if (!gizmo || !gizmo->handleAt(QPointF(p))) at = p, best = d;
        }
    QVERIFY2(at.x() >= 0, name.c_str());
    QTest::mouseClick(viewport(), Qt::LeftButton, mods, at);
}

QPointF GizmoTest::grab(const GizmoHandle& h) {
    const auto g = viewport()->gizmo();
    if (!g) return {};
    const auto at = g->grabPoint(h);
    if (!at) return {};
    const auto picked = g->handleAt(*at);
    return picked && *picked == h ? *at : QPointF();
}

void GizmoTest::scaleBox_DraggedOutwards_ScalesAlongItsAxis_InOneUndoStep() {
    click("blue ball");
    const Transform before = object("blue ball").transform;
    const Vec3 centreBefore = *entityCentre(doc(), idOf(*window_, "blue ball"));
    const QPointF at = grab({TransformKind::Scale, 0, false});
    QVERIFY(!at.isNull());
    const QPointF centre =
        *viewport()->projection().project(*entityCentre(doc(), idOf(*window_, "blue ball")));
    drag(viewport(), at, centre + (at - centre) * 1.5);
    QVERIFY(!viewport()->transforming());
    const Transform after = object("blue ball").transform;
    QVERIFY2(std::abs(after.scale.x - 1.5f * before.scale.x) < 0.05f, qPrintable(str(after.scale)));
    QCOMPARE(after.scale.y, before.scale.y);
    QCOMPARE(after.scale.z, before.scale.z);
    // Scaled about its own centre: it stays where it was.
    QVERIFY(glm::length(*entityCentre(doc(), idOf(*window_, "blue ball")) - centreBefore) < 1e-4f);
    QCOMPARE(editor()->undoStack()->count(), 1);
    editor()->undoStack()->undo();
    QVERIFY(object("blue ball").transform == before);
}

void GizmoTest::zRing_DraggedWithCtrl_RotatesAboutZ_In15DegreeSteps() {
    click("blue ball");
    const Transform before = object("blue ball").transform;
    const QPointF at = grab({TransformKind::Rotate, 2, false});
    QVERIFY(!at.isNull());
    const QPointF c =
        *viewport()->projection().project(*entityCentre(doc(), idOf(*window_, "blue ball")));
    // A quarter turn of the cursor about the centre, Ctrl held after the press.
    const QPointF r = at - c;
    QTest::mousePress(viewport(), Qt::LeftButton, {}, at.toPoint());
    for (int i = 1; i <= 10; ++i) {
        const double a = -M_PI / 2 * i / 10.0;  // Anticlockwise on screen (y grows down).
        moveHeld(viewport(),
                 c + QPointF(r.x() * std::cos(a) - r.y() * std::sin(a),
                             r.x() * std::sin(a) + r.y() * std::cos(a)),
                 Qt::ControlModifier);
    }
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::ControlModifier,
                        viewport()->mapFromGlobal(QCursor::pos()));
    const Transform after = object("blue ball").transform;
    const float turned = after.rotate.z - before.rotate.z;
    QVERIFY2(std::abs(std::abs(turned) - 90.0f) < 1e-3f, qPrintable(str(after.rotate)));
    QCOMPARE(after.rotate.x, before.rotate.x);
    QCOMPARE(after.rotate.y, before.rotate.y);
    QCOMPARE(editor()->undoStack()->count(), 1);
}

// A drag along an arrow carries the point grabbed under the cursor: the distance moved is
// what the drag's pixels span along the axis at that depth (alongAxis), within 2 % (the press
// lands on a whole pixel, up to half a pixel off the axis' line).
void GizmoTest::xArrow_MovesAlongX_AndInLocalAxesAlongTheObjectsOwnX() {
    click("blue ball");
    const ObjectId id = idOf(*window_, "blue ball");
    Vec3 before = object("blue ball").transform.translate;
    Vec3 centre = *entityCentre(doc(), id);
    const ViewProjection view = viewport()->projection();
    QPointF at = QPointF(grab({TransformKind::Move, 0, false}).toPoint());
    QVERIFY(!at.isNull());
    QPointF to = at + 40.0 * screenDirection(view, centre, Vec3(1, 0, 0));
    drag(viewport(), at, to);
    Vec3 delta = object("blue ball").transform.translate - before;
    double expected = alongAxis(view, centre, Vec3(1, 0, 0), at, to);
    QVERIFY2(expected > 0.1 && std::abs(delta.x - expected) <= 0.02 * expected && delta.y == 0.0f &&
                 delta.z == 0.0f,
             qPrintable(str(delta) + QStringLiteral(", expected x %1").arg(expected)));

    // Turned 45 degrees about Z, in local axes the X arrow follows the ball's own X.
    QTest::keyClicks(viewport(), QStringLiteral("rz45"));
    QTest::keyClick(viewport(), Qt::Key_Return);
    viewport()->setLocalOrientation(true);
    before = object("blue ball").transform.translate;
    centre = *entityCentre(doc(), id);
    const Vec3 ownX = glm::normalize(Vec3(1, 1, 0));
    at = QPointF(grab({TransformKind::Move, 0, false}).toPoint());
    QVERIFY(!at.isNull());
    to = at + 35.0 * screenDirection(view, centre, ownX);
    drag(viewport(), at, to);
    delta = object("blue ball").transform.translate - before;
    expected = alongAxis(view, centre, ownX, at, to);
    QVERIFY2(
        expected > 0.1 && std::abs(glm::dot(delta, ownX) - expected) <= 0.02 * expected &&
            glm::length(glm::cross(delta, ownX)) < 1e-3f,
        qPrintable(str(delta) + QStringLiteral(", expected %1 along (1, 1, 0)").arg(expected)));
    QCOMPARE(editor()->undoStack()->count(), 3);
}

// A drag on the XZ square moves in the floor's plane and keeps the point grabbed there under
// the cursor: where the view rays through the press and the release meet the plane.
void GizmoTest::planeSquare_MovesInItsPlaneOnly() {
    click("blue ball");
    const Vec3 before = object("blue ball").transform.translate;
    const Vec3 centre = *entityCentre(doc(), idOf(*window_, "blue ball"));
    const ViewProjection view = viewport()->projection();
    // The square between X and Z (normal Y): the floor's plane.
    const QPointF at = QPointF(grab({TransformKind::Move, 1, true}).toPoint());
    QVERIFY(!at.isNull());
    const QPointF to = at + QPointF(30, 20);
    drag(viewport(), at, to);
    const Vec3 delta = object("blue ball").transform.translate - before;
    const Vec3 grabbed = onHorizontalPlane(view, at, centre.y);
    const Vec3 expected = onHorizontalPlane(view, to, centre.y) - grabbed;
    QVERIFY2(std::abs(delta.y) < 1e-4f && glm::length(expected) > 0.1f &&
                 glm::length(delta - expected) <= 0.02f * glm::length(expected),
             qPrintable(str(delta) + QStringLiteral(", expected ") + str(expected)));
    // The grabbed point, moved, is under the release point again.
    const QPointF landed = *view.project(grabbed + delta);
    QVERIFY2(length(landed - to) < 1.0,
             qPrintable(QStringLiteral("%1, %2").arg(landed.x()).arg(landed.y())));
}

void GizmoTest::ctrlAndShiftClick_SelectSeveral_GMovesAll_OneUndoStep() {
    click("blue ball");
    click("chrome ball", Qt::ControlModifier);
    click("green ball", Qt::ShiftModifier);
    const std::vector<ObjectId> three = {idOf(*window_, "blue ball"), idOf(*window_, "chrome ball"),
                                         idOf(*window_, "green ball")};
    QVERIFY(editor()->selectedIds() == three);
    QCOMPARE(editor()->selection(), three.back());  // The last picked is the active one.
    // Ctrl-click again takes one out.
    click("chrome ball", Qt::ControlModifier);
    QVERIFY((editor()->selectedIds() == std::vector{three[0], three[2]}));
    const SceneDocument before = doc();
    QTest::keyClicks(viewport(), QStringLiteral("gx1"));
    QTest::keyClick(viewport(), Qt::Key_Return);
    for (const char* n : {"blue ball", "green ball"}) {
        const Vec3 d = object(n).transform.translate -
                       before.findObject(idOf(*window_, n))->transform.translate;
        QVERIFY2(glm::length(d - Vec3(1, 0, 0)) < 1e-5f, n);
    }
    QVERIFY(object("chrome ball").transform == before.findObject(three[1])->transform);
    QCOMPARE(editor()->undoStack()->count(), 1);
    editor()->undoStack()->undo();
    QVERIFY(doc().sameContent(before));
    // A plain click on one of them selects it alone.
    click("blue ball");
    QVERIFY(editor()->selectedIds() == std::vector{three[0]});
}

void GizmoTest::gizmoArrow_MovesTheWholeGroup() {
    click("blue ball");
    click("glass ball", Qt::ControlModifier);
    const SceneDocument before = doc();
    // The gizmo sits at the mean of the selected centres.
    const Vec3 pivot = 0.5f * (*entityCentre(doc(), idOf(*window_, "blue ball")) +
                               *entityCentre(doc(), idOf(*window_, "glass ball")));
    const ViewProjection view = viewport()->projection();
    const QPointF at = QPointF(grab({TransformKind::Move, 0, false}).toPoint());
    QVERIFY(!at.isNull());
    const QPointF to = at + 40.0 * screenDirection(view, pivot, Vec3(1, 0, 0));
    drag(viewport(), at, to);
    const double expected = alongAxis(view, pivot, Vec3(1, 0, 0), at, to);
    const Vec3 a = object("blue ball").transform.translate -
                   before.findObject(idOf(*window_, "blue ball"))->transform.translate;
    const Vec3 b = object("glass ball").transform.translate -
                   before.findObject(idOf(*window_, "glass ball"))->transform.translate;
    QVERIFY2(expected > 0.1 && std::abs(a.x - expected) <= 0.02 * expected && a.y == 0.0f &&
                 a.z == 0.0f && glm::length(a - b) < 1e-5f,
             qPrintable(str(a) + str(b) + QStringLiteral(", expected x %1").arg(expected)));
    QCOMPARE(editor()->undoStack()->count(), 1);
    editor()->undoStack()->undo();
    QVERIFY(doc().sameContent(before));
}

void GizmoTest::boxSelect_SelectsTheBallsWhoseCentresAreInside() {
    // A box about the blue and the glass ball's centres (with a margin).
    const ViewProjection view = viewport()->projection();
    const QPointF a = *view.project(*entityCentre(doc(), idOf(*window_, "blue ball")));
    const QPointF b = *view.project(*entityCentre(doc(), idOf(*window_, "glass ball")));
    const QRectF box = QRectF(a, b).normalized().adjusted(-6, -6, 6, 6);
    std::vector<ObjectId> expected;
    for (const Object& o : doc().objects)
        if (!std::holds_alternative<PlaneGeometry>(o.geometry))
            if (const auto p = view.project(*entityCentre(doc(), o.id)); p && box.contains(*p))
                expected.push_back(o.id);
    QVERIFY(expected.size() >= 2);
    // B, then a drag that starts on a ball: with B it draws a box instead of moving it.
    QTest::keyClick(viewport(), Qt::Key_B);
    const SceneDocument before = doc();
    drag(viewport(), box.topLeft(), box.bottomRight());
    std::vector<ObjectId> got = editor()->selectedIds();
    std::sort(got.begin(), got.end());
    std::sort(expected.begin(), expected.end());
    QVERIFY2(got == expected,
             qPrintable(
                 QStringLiteral("%1 selected, %2 expected").arg(got.size()).arg(expected.size())));
    QVERIFY(doc().sameContent(before));  // Nothing moved, no walls taken.
    QCOMPARE(editor()->undoStack()->count(), 0);

    // A box about the whole image takes every ball and the light, never a wall.
    QTest::keyClick(viewport(), Qt::Key_B);
    const QRect all(QPoint(1, 1), QPoint(viewport()->width() - 2, viewport()->height() - 2));
    drag(viewport(), all.topLeft(), all.bottomRight());
    int balls = 0;
    for (const Object& o : doc().objects) {
        const auto p = view.project(*entityCentre(doc(), o.id));
        const bool inside =
            !std::holds_alternative<PlaneGeometry>(o.geometry) && p && all.contains(p->toPoint());
        balls += inside;
        QVERIFY2(editor()->isSelected(o.id) == inside, o.name.c_str());
    }
    QVERIFY(balls >= 5);
    QVERIFY(editor()->isSelected(doc().lights.front().id));
    editor()->setSelection(expected);

    // Shift adds a box's contents to the selection: the light's glyph this time.
    const QPointF light = viewport()->lightGlyphs().front().centre;
    QTest::keyClick(viewport(), Qt::Key_B);
    drag(viewport(), light - QPointF(8, 8), light + QPointF(8, 8), Qt::ShiftModifier);
    QCOMPARE(editor()->selectedIds().size(), expected.size() + 1);
    QVERIFY(editor()->isSelected(doc().lights.front().id));
}

void GizmoTest::delete_OfAGroup_IsOneUndoStep() {
    click("blue ball");
    click("chalk ball", Qt::ControlModifier);
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier,
                      viewport()->lightGlyphs().front().centre.toPoint());
    QCOMPARE(editor()->selectedIds().size(), std::size_t(3));
    const SceneDocument before = doc();
    QTest::keyClick(viewport(), Qt::Key_Delete);
    QCOMPARE(idOf(*window_, "blue ball"), kNoObject);
    QCOMPARE(idOf(*window_, "chalk ball"), kNoObject);
    QVERIFY(doc().lights.empty());
    QCOMPARE(doc().objects.size(), before.objects.size() - 2);
    QVERIFY(editor()->selectedIds().empty());
    QCOMPARE(editor()->undoStack()->count(), 1);
    QTest::keyClick(viewport(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(doc().sameContent(before));
}

void GizmoTest::duplicate_OfAGroup_SelectsTheCopies() {
    click("blue ball");
    click("chalk ball", Qt::ControlModifier);
    const std::size_t n = doc().objects.size();
    QTest::keyClick(viewport(), Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(doc().objects.size(), n + 2);
    QCOMPARE(editor()->selectedIds().size(), std::size_t(2));
    for (ObjectId id : editor()->selectedIds()) {
        QVERIFY(id != idOf(*window_, "blue ball") && id != idOf(*window_, "chalk ball"));
        QVERIFY(doc().findObject(id));
    }
    QCOMPARE(editor()->undoStack()->count(), 1);
}

void GizmoTest::outliner_CtrlClick_SelectsSeveral_AndFollowsTheViewport() {
    OutlinerView* tree = window_->outliner();
    const ObjectId blue = idOf(*window_, "blue ball"), green = idOf(*window_, "green ball");
    const auto clickRow = [&](ObjectId id, Qt::KeyboardModifiers mods) {
        const QRect r = tree->visualRect(tree->indexOf(id));
        QVERIFY(r.isValid());
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, mods, r.center());
    };
    clickRow(blue, {});
    clickRow(green, Qt::ControlModifier);
    QVERIFY((editor()->selectedIds() == std::vector{blue, green}));
    QCOMPARE(tree->selectionModel()->selectedRows().size(), 2);
    // Selected in the viewport, the rows follow.
    click("chrome ball", Qt::ShiftModifier);
    QCOMPARE(tree->selectionModel()->selectedRows().size(), 3);
    QVERIFY(tree->selectionModel()->isSelected(tree->indexOf(idOf(*window_, "chrome ball"))));
}

void GizmoTest::propertyPanel_WithSeveralSelected_SaysWhichOneItShows() {
    click("blue ball");
    QVERIFY(!window_->propertyPanel()->findChild<QLabel*>(QStringLiteral("selectionSummary")));
    click("glass ball", Qt::ControlModifier);
    const auto* summary =
        window_->propertyPanel()->findChild<QLabel*>(QStringLiteral("selectionSummary"));
    QVERIFY(summary);
    QVERIFY2(summary->text().contains(QStringLiteral("2 selected")) &&
                 summary->text().contains(QStringLiteral("glass ball")),
             qPrintable(summary->text()));
    // Its fields are the active one's.
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("transform"), "translate",
                                                Vec3(0.0f, 1.0f, -4.0f)));
    QVERIFY(object("glass ball").transform.translate == Vec3(0.0f, 1.0f, -4.0f));
}

void GizmoTest::ctrlZ_DuringAGizmoDrag_CancelsIt_AndUndoesNothingElse() {
    click("blue ball");
    QTest::keyClicks(viewport(), QStringLiteral("gy1"));  // An earlier step that must survive.
    QTest::keyClick(viewport(), Qt::Key_Return);
    const SceneDocument before = doc();
    const QPointF at = grab({TransformKind::Move, 0, false});
    QVERIFY(!at.isNull());
    QTest::mousePress(viewport(), Qt::LeftButton, {}, at.toPoint());
    for (int i = 1; i <= 4; ++i) moveHeld(viewport(), at + QPointF(10 * i, 0));
    QVERIFY(viewport()->transforming());
    QVERIFY(!doc().sameContent(before));
    QTest::keyClick(viewport(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(!viewport()->transforming());
    QVERIFY(doc().sameContent(before));
    QCOMPARE(editor()->undoStack()->count(), 1);
    // The rest of the drag does nothing.
    moveHeld(viewport(), at + QPointF(60, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, (at + QPointF(60, 0)).toPoint());
    QVERIFY(doc().sameContent(before));
    QCOMPARE(editor()->undoStack()->count(), 1);
}

void GizmoTest::ctrlZ_DuringAKeyGesture_CancelsIt() {
    click("blue ball");
    const SceneDocument before = doc();
    const QPoint c = viewport()->rect().center();
    QTest::mouseMove(viewport(), c);
    QTest::keyClick(viewport(), Qt::Key_G);
    for (int i = 1; i <= 4; ++i) QTest::mouseMove(viewport(), c + QPoint(12 * i, 0));
    QVERIFY(!doc().sameContent(before));
    QTest::keyClick(viewport(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(!viewport()->transforming());
    QVERIFY(doc().sameContent(before));
    QCOMPARE(editor()->undoStack()->count(), 0);
}

void GizmoTest::undoFromTheMenu_DuringADrag_EndsTheDrag() {
    click("blue ball");
    const SceneDocument before = doc();
    const QPointF at = grab({TransformKind::Move, 0, false});
    QVERIFY(!at.isNull());
    QTest::mousePress(viewport(), Qt::LeftButton, {}, at.toPoint());
    for (int i = 1; i <= 4; ++i) moveHeld(viewport(), at + QPointF(10 * i, 0));
    QCOMPARE(editor()->undoStack()->count(), 1);
    editor()->undoStack()->undo();  // What Edit -> Undo does.
    QVERIFY(!viewport()->transforming());
    QVERIFY(doc().sameContent(before));
    moveHeld(viewport(), at + QPointF(60, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, (at + QPointF(60, 0)).toPoint());
    QVERIFY(doc().sameContent(before));
    QVERIFY(!editor()->undoStack()->canUndo());
}

void GizmoTest::orbitAboutAFarWall_KeepsTheViewInsideTheRoom() {
    // Nothing selected: the orbit turns about the back wall under the cursor, 14 units away,
    // which unclipped swings the view out through the side wall.
    editor()->setSelection(kNoObject);
    Viewport* v = viewport();
    const QPoint c = v->rect().center();
    const auto px = v->pixelAt(c);
    QVERIFY(px);
    QCOMPARE(v->frame()->idAt(px->x(), px->y()), idOf(*window_, "back wall"));
    const Vec3 forwardBefore = glm::normalize(v->viewCamera().target - v->viewCamera().position);
    QTest::mousePress(v, Qt::RightButton, {}, c);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(v, c + QPoint(10 * i, 0));
    QTest::mouseRelease(v, Qt::RightButton, {}, c + QPoint(100, 0));
    const Camera& cam = v->viewCamera();
    for (const Object& o : doc().objects)
        if (const auto* plane = std::get_if<PlaneGeometry>(&o.geometry))
            QVERIFY2(glm::dot(cam.position - plane->point, plane->normal) > 0.0f,
                     qPrintable(QString::fromStdString("behind the " + o.name + " at ") +
                                str(cam.position)));
    // It turned as far as the drag says: 100 pixels across at 0.4 degrees a pixel is a yaw of
    // 40 degrees about the vertical, the pitch left as it was (the wall only moves the camera
    // along its line of sight, never turns it).
    const Vec3 forward = glm::normalize(cam.target - cam.position);
    const auto heading = [](const Vec3& f) { return glm::degrees(std::atan2(f.x, -f.z)); };
    const float yaw = std::remainder(heading(forward) - heading(forwardBefore), 360.0f);
    QVERIFY2(std::abs(std::abs(yaw) - 40.0f) < 0.5f, qPrintable(QString::number(yaw)));
    QVERIFY2(std::abs(forward.y - forwardBefore.y) < 1e-3f, qPrintable(str(forward)));
    QCOMPARE(editor()->undoStack()->count(), 0);
}

QTEST_MAIN(GizmoTest)
#include "gizmo_test.moc"
