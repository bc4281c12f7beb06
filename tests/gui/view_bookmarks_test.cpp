// View bookmarks in the designer (View -> Bookmarks): adding the view as it is, going back to
// one without moving the scene camera, names that are refused, renaming and removing as undo
// steps, saving, and the cameras of an imported asset as bookmarks or the scene camera, as the
// user chooses (offscreen).
#include "shell/view_bookmarks.h"

#include <QAction>
#include <QMenu>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>
#include <optional>

#include "gui_test_support.h"
#include "shell/error_reporter.h"
#include "shell/user_confirmation.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

class ViewBookmarksTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void bookmarkThisView_AsksANameAndKeepsTheViewAsOneUndoStep();
    void goingToABookmark_MovesTheViewNotTheSceneCamera_AndTheFrameFollows();
    void emptyOrTakenNames_AreRefusedAndAskedAgain();
    void renameAndRemove_AreUndoSteps();
    void theMenu_ListsTheViews_AndGoesToThem();
    void saveAndOpen_KeepsTheViews();
    void importedCameras_AsTheUserChooses();

private:
    const SceneDocument& doc() { return window_->editor()->document(); }
    ViewBookmarks* bookmarks() { return window_->viewBookmarks(); }
    /// Answers the next name questions with `names`, in turn (then cancels).
    void answerNames(QStringList names);
    /// Mean colour of the viewport's frame.
    Vec3 meanColour();

    std::unique_ptr<MainWindow> window_;
    QStringList errors_;
};

void ViewBookmarksTest::init() {
    errors_.clear();
    setErrorHandler([this](const QString&, const QString& text) { errors_ << text; });
    QVERIFY(openRoomWindow(window_));
}

void ViewBookmarksTest::cleanup() {
    setTextHandler({});
    setChoiceHandler({});
    setErrorHandler({});
    if (!window_) return;
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

void ViewBookmarksTest::answerNames(QStringList names) {
    setTextHandler(
        [names](const QString&, const QString&, const QString&) mutable -> std::optional<QString> {
            if (names.isEmpty()) return std::nullopt;
            return names.takeFirst();
        });
}

Vec3 ViewBookmarksTest::meanColour() {
    const DisplayFrame& f = *window_->viewport()->frame();
    Vec3 sum(0.0f);
    for (const Vec3& c : f.color) sum += c;
    return sum / float(std::max<std::size_t>(f.color.size(), 1));
}

void ViewBookmarksTest::bookmarkThisView_AsksANameAndKeepsTheViewAsOneUndoStep() {
    window_->viewport()->setAxisView(AxisView::Top);
    const Camera top = window_->viewport()->viewCamera();
    const Camera scene = doc().camera;
    QString offered;
    setTextHandler([&](const QString&, const QString&, const QString& initial) {
        offered = initial;
        return std::optional<QString>(QStringLiteral(" from above "));
    });
    bookmarks()->bookmarkView();
    QCOMPARE(offered, QStringLiteral("View 1"));
    QCOMPARE(doc().views.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(doc().views[0].name), QStringLiteral("from above"));
    QVERIFY(doc().views[0].camera == top);
    QVERIFY(doc().camera == scene);
    QCOMPARE(window_->editor()->undoStack()->count(), 1);
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().views.empty());
    // Cancelled: nothing changes.
    answerNames({});
    bookmarks()->bookmarkView();
    QVERIFY(doc().views.empty());
    QVERIFY(errors_.isEmpty());
}

void ViewBookmarksTest::goingToABookmark_MovesTheViewNotTheSceneCamera_AndTheFrameFollows() {
    window_->viewport()->setAxisView(AxisView::Top);
    answerNames({QStringLiteral("top")});
    bookmarks()->bookmarkView();
    QVERIFY(settle(*window_));
    const Vec3 fromTop = meanColour();
    window_->viewport()->viewThroughSceneCamera();
    QVERIFY(window_->viewport()->throughSceneCamera());
    QVERIFY(settle(*window_));
    const Vec3 throughScene = meanColour();
    QVERIFY(glm::length(fromTop - throughScene) > 1e-3f);
    const Camera scene = doc().camera;
    const int steps = window_->editor()->undoStack()->count();

    QVERIFY(bookmarks()->goTo("top"));
    QVERIFY(window_->viewport()->viewCamera() == doc().findView("top")->camera);
    QVERIFY(!window_->viewport()->throughSceneCamera());
    QVERIFY(doc().camera == scene);
    QCOMPARE(window_->editor()->undoStack()->count(), steps);
    QVERIFY(settle(*window_));
    QVERIFY(glm::length(meanColour() - fromTop) < 1e-5f);
    QVERIFY(!bookmarks()->goTo("nowhere"));

    // Scene Camera from View takes the bookmark as the scene camera, as one undo step.
    window_->viewport()->sceneCameraFromView();
    QVERIFY(doc().camera == doc().findView("top")->camera);
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 1);
}

void ViewBookmarksTest::emptyOrTakenNames_AreRefusedAndAskedAgain() {
    answerNames({QStringLiteral("front")});
    bookmarks()->bookmarkView();
    QStringList offered;
    QStringList names{QStringLiteral("  "), QStringLiteral("front"), QStringLiteral("side")};
    setTextHandler([&](const QString&, const QString&, const QString& initial) {
        offered << initial;
        return std::optional<QString>(names.takeFirst());
    });
    bookmarks()->bookmarkView();
    QCOMPARE(errors_.size(), 2);
    QVERIFY2(errors_[0].contains(QStringLiteral("needs a name")), qPrintable(errors_[0]));
    QVERIFY2(errors_[1].contains(QStringLiteral("already a view named \"front\"")),
             qPrintable(errors_[1]));
    // Asked again with what was typed.
    QCOMPARE(offered, (QStringList{QStringLiteral("View 1"), QStringLiteral("  "),
                                   QStringLiteral("front")}));
    QCOMPARE(doc().views.size(), std::size_t(2));
    QVERIFY(doc().findView("side"));
    QCOMPARE(freeViewName(doc()), QStringLiteral("View 1"));
}

void ViewBookmarksTest::renameAndRemove_AreUndoSteps() {
    answerNames({QStringLiteral("a"), QStringLiteral("b")});
    bookmarks()->bookmarkView();
    bookmarks()->bookmarkView();
    const int steps = window_->editor()->undoStack()->count();
    // Renaming to its own name is no edit; to another view's name is refused.
    answerNames({QStringLiteral("a")});
    bookmarks()->rename("a");
    QCOMPARE(window_->editor()->undoStack()->count(), steps);
    answerNames({QStringLiteral("b"), QStringLiteral("c")});
    bookmarks()->rename("a");
    QCOMPARE(errors_.size(), 1);
    QVERIFY(!doc().findView("a") && doc().findView("c"));
    QCOMPARE(doc().views[0].name, std::string("c"));  // in its place
    bookmarks()->remove("b");
    QCOMPARE(doc().views.size(), std::size_t(1));
    QCOMPARE(window_->editor()->undoStack()->count(), steps + 2);
    window_->editor()->undoStack()->undo();
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().findView("a") && doc().findView("b"));
}

void ViewBookmarksTest::theMenu_ListsTheViews_AndGoesToThem() {
    window_->viewport()->setAxisView(AxisView::Right);
    answerNames({QStringLiteral("R&D")});
    bookmarks()->bookmarkView();
    window_->viewport()->viewThroughSceneCamera();
    QMenu* menu = bookmarks()->menu();
    Q_EMIT menu->aboutToShow();
    QAction* go = window_->findChild<QAction*>(QStringLiteral("goToView:R&D"));
    QVERIFY(go);
    QCOMPARE(go->text(), QStringLiteral("R&&D"));  // shown as written, no mnemonic
    go->trigger();
    QVERIFY(window_->viewport()->viewCamera() == doc().findView("R&D")->camera);
    QVERIFY(!window_->viewport()->throughSceneCamera());
    // The menu follows an undo.
    window_->editor()->undoStack()->undo();
    Q_EMIT menu->aboutToShow();
    QVERIFY(!window_->findChild<QAction*>(QStringLiteral("goToView:R&D")));
}

void ViewBookmarksTest::saveAndOpen_KeepsTheViews() {
    window_->viewport()->setAxisView(AxisView::Top);
    answerNames({QStringLiteral("top")});
    bookmarks()->bookmarkView();
    const std::vector<ViewBookmark> views = doc().views;
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("views.scene.json"));
    QVERIFY(window_->saveFile(path));
    QVERIFY(window_->openFile(scenePath("reference-room.scene.json")));
    QVERIFY(doc().views.empty());
    QVERIFY(window_->openFile(path));
    QVERIFY(doc().views == views);
}

void ViewBookmarksTest::importedCameras_AsTheUserChooses() {
    // A triangle seen by two cameras: "Eye" at (0, 0.5, 3), "Side" at (3, 0.5, 0) looking at it.
    const QString asset = QStringLiteral(RAYSTUDIO_TEST_DATA "/meshes/two_cameras.gltf");
    const Camera scene = doc().camera;
    auto import = [&](int choice) -> bool {
        QStringList asked;
        setChoiceHandler(
            [&asked, choice](const QString&, const QString& text, const QStringList& choices) {
                asked << text << choices;
                return choice;
            });
        const std::size_t objects = doc().objects.size();
        window_->importMesh(asset);
        if (!QTest::qWaitFor([&] { return doc().objects.size() == objects + 1; }, 20000))
            return false;
        // Asked once, naming both cameras' count and the first, with the three answers.
        return asked.size() == 4 && asked[0].contains(QStringLiteral("2 cameras")) &&
               asked[0].contains(QStringLiteral("\"Eye\"")) &&
               asked[1] == QStringLiteral("Look Through It");
    };

    // Bookmarks: both cameras, placed with the asset; the scene camera stays.
    QVERIFY(import(1));
    QCOMPARE(doc().views.size(), std::size_t(2));
    const ViewBookmark* eye = doc().findView("Eye");
    const ViewBookmark* side = doc().findView("Side");
    QVERIFY(eye && side);
    QVERIFY(doc().camera == scene);
    const Object& placed = doc().objects[doc().objects.size() - 1];
    const Vec3 eyeAt = Vec3(placed.transform.matrix() * glm::vec4(0.0f, 0.5f, 3.0f, 1.0f));
    QVERIFY2(glm::length(eye->camera.position - eyeAt) < 1e-4f, "placed as the asset");
    QVERIFY(std::abs(side->camera.fovY - float(0.8 * 180.0 / 3.14159265358979)) < 1e-3f);
    QVERIFY2(window_->statusBar()->currentMessage().contains(QStringLiteral("2 cameras")),
             qPrintable(window_->statusBar()->currentMessage()));
    // One undo takes the asset and its views away together.
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().views.empty());

    // Look through it: the first is the scene camera, and both are bookmarks.
    QVERIFY(import(0));
    QCOMPARE(doc().views.size(), std::size_t(2));
    QVERIFY(doc().camera == doc().findView("Eye")->camera);
    window_->editor()->undoStack()->undo();
    QVERIFY(doc().camera == scene);

    // Left out (or the box closed): no views, the scene camera stays.
    for (int choice : {2, -1}) {
        QVERIFY(import(choice));
        QVERIFY(doc().views.empty());
        QVERIFY(doc().camera == scene);
        window_->editor()->undoStack()->undo();
    }
}

QTEST_MAIN(ViewBookmarksTest)
#include "view_bookmarks_test.moc"
