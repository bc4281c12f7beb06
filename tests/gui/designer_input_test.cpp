// Keyboard and mouse input of the designer with real events: shortcuts from any focus, the
// shortcut list, drags that outlive a frame resize or a dolly, and closing during a render.
// Runs offscreen and, for the X11 key bindings (Ctrl+E is end-of-line there), under Xvfb.
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QElapsedTimer>
#include <QMenuBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QWheelEvent>
#include <QtTest>
#include <map>

#include "gui_test_support.h"
#include "panels/property_panel.h"
#include "shell/user_confirmation.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

/// The action whose menu text (without mnemonics) is `text`, or nullptr.
QAction* actionNamed(const QWidget& window, const QString& text) {
    for (QAction* a : window.findChildren<QAction*>())
        if (a->iconText() == text) return a;
    return nullptr;
}

/// Closes the next modal dialog (a file dialog an action opens) and records its title.
void closeNextModal(QString* title) {
    QTimer::singleShot(100, [title] {
        if (QWidget* modal = QApplication::activeModalWidget()) {
            *title = modal->windowTitle();
            modal->close();
        }
    });
}

}  // namespace

class DesignerInputTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void saveAs_HasAShortcutEvenWhereThePlatformDefinesNone();
    void noTwoActionsShareAShortcut();
    void commandShortcuts_WorkWhileAPropertyFieldHasFocus();
    void plainKeys_StayWithTheFocusedField();
    void keyboardShortcutsDialog_ListsEveryMenuShortcut();
    void pressThenFrameResize_DoesNotStartADrag();
    void wheelDuringObjectDrag_KeepsTheDolly();
    void closingDuringRenderImage_CancelsItAndReturnsPromptly();

private:
    /// Selects the blue ball and focuses the first spin box of its property panel.
    QAbstractSpinBox* focusPropertyField();

    std::unique_ptr<MainWindow> window_;
};

void DesignerInputTest::init() {
    QVERIFY(openRoomWindow(window_));
}

void DesignerInputTest::cleanup() {
    if (!window_) return;
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

QAbstractSpinBox* DesignerInputTest::focusPropertyField() {
    window_->editor()->setSelection(idOf(*window_, "blue ball"));
    const auto spins = window_->propertyPanel()->findChildren<QAbstractSpinBox*>();
    if (spins.isEmpty()) return nullptr;
    QAbstractSpinBox* spin = spins.first();
    window_->activateWindow();  // A dialog that just closed may have kept the activation.
    if (!QTest::qWaitForWindowActive(window_.get())) return nullptr;
    spin->setFocus(Qt::OtherFocusReason);
    return QApplication::focusWidget() == spin ? spin : nullptr;
}

void DesignerInputTest::saveAs_HasAShortcutEvenWhereThePlatformDefinesNone() {
    QAction* saveAs = actionNamed(*window_, QStringLiteral("Save As"));
    QVERIFY(saveAs);
    const QList<QKeySequence> standard = QKeySequence::keyBindings(QKeySequence::SaveAs);
    if (standard.isEmpty())
        QCOMPARE(saveAs->shortcuts(),
                 QList<QKeySequence>{QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)});
    else
        QCOMPARE(saveAs->shortcuts(), standard);
    QAction* quit = actionNamed(*window_, QStringLiteral("Quit"));
    QVERIFY(quit && !quit->shortcuts().isEmpty());
}

void DesignerInputTest::noTwoActionsShareAShortcut() {
    // An ambiguous shortcut fires neither action: the fallbacks must not collide.
    std::map<QString, QString> owner;
    for (const QAction* a : window_->findChildren<QAction*>()) {
        for (const QKeySequence& k : a->shortcuts()) {
            const auto [it, fresh] = owner.emplace(k.toString(), a->iconText());
            QVERIFY2(fresh || it->second == a->iconText(),
                     qPrintable(k.toString() + ": " + it->second + " and " + a->iconText()));
        }
    }
}

void DesignerInputTest::commandShortcuts_WorkWhileAPropertyFieldHasFocus() {
    // Ctrl+E (Export Image) while a property spin box has focus opens the export dialog.
    QAbstractSpinBox* spin = focusPropertyField();
    QVERIFY(spin);
    QString dialogTitle;
    closeNextModal(&dialogTitle);
    QTest::keyClick(spin, Qt::Key_E, Qt::ControlModifier);
    // The dialog names the size it writes: the viewport's frame, not the output size.
    QCOMPARE(dialogTitle, QStringLiteral("Export Current Frame (160x90, the viewport's size)"));

    // Ctrl+Z undoes the last document edit instead of the field's text.
    const SceneDocument before = window_->editor()->document();
    SceneDocument moved = before;
    moveBy(moved, idOf(*window_, "green ball"), Vec3(0.5f, 0.0f, 0.0f));
    window_->editor()->edit(QStringLiteral("move"), moved);
    spin = focusPropertyField();
    QVERIFY(spin);
    QTest::keyClick(spin, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(window_->editor()->document().sameContent(before));

    // Ctrl+D duplicates the selection from the field too.
    const std::size_t objects = window_->editor()->document().objects.size();
    QTest::keyClick(focusPropertyField(), Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(window_->editor()->document().objects.size(), objects + 1);
}

void DesignerInputTest::plainKeys_StayWithTheFocusedField() {
    // Delete and Backspace edit the field's text; they must not delete the selected object.
    QAbstractSpinBox* spin = focusPropertyField();
    QVERIFY(spin);
    const std::size_t objects = window_->editor()->document().objects.size();
    QTest::keyClick(spin, Qt::Key_End);
    QTest::keyClick(spin, Qt::Key_Backspace);
    QTest::keyClick(spin, Qt::Key_Delete);
    QCOMPARE(window_->editor()->document().objects.size(), objects);
}

void DesignerInputTest::keyboardShortcutsDialog_ListsEveryMenuShortcut() {
    QAction* open = window_->findChild<QAction*>(QStringLiteral("keyboardShortcuts"));
    QVERIFY(open);
    open->trigger();
    QDialog* dialog = nullptr;
    for (QDialog* d : window_->findChildren<QDialog*>())
        if (d->isVisible() && d->findChild<QTableWidget*>(QStringLiteral("shortcutsTable")))
            dialog = d;
    QVERIFY(dialog);
    auto* table = dialog->findChild<QTableWidget*>(QStringLiteral("shortcutsTable"));
    std::map<QString, QString> listed;
    for (int r = 0; r < table->rowCount(); ++r)
        listed[table->item(r, 0)->text()] = table->item(r, 1)->text();

    // Every action with a shortcut is listed once, with its keys.
    int withKeys = 0;
    for (const QAction* a : window_->findChildren<QAction*>()) {
        if (a->shortcuts().isEmpty()) continue;
        ++withKeys;
        const QString keys = a->shortcuts().first().toString(QKeySequence::NativeText);
        bool found = false;
        for (const auto& [command, k] : listed)
            found |= command.endsWith(QStringLiteral(" > ") + a->iconText()) && k.startsWith(keys);
        QVERIFY2(found, qPrintable(a->iconText() + " (" + keys + ") is not listed"));
    }
    QCOMPARE(table->rowCount(), withKeys);
    const QList<QKeySequence> saveAsKeys =
        actionNamed(*window_, QStringLiteral("Save As"))->shortcuts();
    QVERIFY(!saveAsKeys.isEmpty());
    const QString saveAs = saveAsKeys.first().toString(QKeySequence::NativeText);
    QCOMPARE(listed[QStringLiteral("File > Save As")], saveAs);
    QCOMPARE(listed[QStringLiteral("File > Export Image")],
             QKeySequence(Qt::CTRL | Qt::Key_E).toString(QKeySequence::NativeText));
    dialog->close();
}

void DesignerInputTest::pressThenFrameResize_DoesNotStartADrag() {
    const ObjectId blue = idOf(*window_, "blue ball");
    Viewport* v = window_->viewport();
    const auto [x, y] = pixelOf(*v->frame(), blue);
    const QPoint start = v->widgetPointOf(x, y);
    QTest::mousePress(v, Qt::LeftButton, {}, start);
    QCOMPARE(window_->editor()->selection(), blue);

    // The viewport changes shape before the drag starts (the frame follows it, at scale 1/2):
    // the press point is off the image.
    for (const QSize size : {QSize(20, 180), QSize(320, 12)}) {
        QVERIFY(traceViewport(*window_, size, 2));
        QCOMPARE(v->frame()->width, size.width() / 2);
        if (!v->pixelAt(start)) break;
    }
    QVERIFY(!v->pixelAt(start));
    const SceneDocument before = window_->editor()->document();
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(v, start + QPoint(4 * i, 0));
    QTest::mouseRelease(v, Qt::LeftButton, {}, start + QPoint(20, 0));
    QVERIFY(window_->editor()->document().sameContent(before));
    QVERIFY(!window_->editor()->undoStack()->canUndo());
}

void DesignerInputTest::wheelDuringObjectDrag_KeepsTheDolly() {
    const ObjectId blue = idOf(*window_, "blue ball");
    Viewport* v = window_->viewport();
    const auto [x, y] = pixelOf(*v->frame(), blue);
    const QPoint start = v->widgetPointOf(x, y);
    const Camera cameraBefore = v->viewCamera();
    const Camera sceneCamera = window_->editor()->document().camera;
    const Vec3 ballBefore = window_->editor()->document().findObject(blue)->transform.translate;

    QTest::mousePress(v, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 3; ++i) QTest::mouseMove(v, start + QPoint(4 * i, 0));
    const QPoint at = start + QPoint(12, 0);
    QWheelEvent wheel(at, v->mapToGlobal(at), QPoint(), QPoint(0, 240), Qt::LeftButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(v, &wheel);
    const Camera dollied = v->viewCamera();
    QVERIFY(!(dollied == cameraBefore));
    for (int i = 4; i <= 8; ++i) QTest::mouseMove(v, start + QPoint(4 * i, 0));
    QTest::mouseRelease(v, Qt::LeftButton, {}, start + QPoint(32, 0));

    const SceneDocument& after = window_->editor()->document();
    QVERIFY(v->viewCamera() == dollied);   // The drag steps after the wheel kept it.
    QVERIFY(after.camera == sceneCamera);  // A dolly moves the view, never the document.
    QVERIFY(after.findObject(blue)->transform.translate.x > ballBefore.x + 0.05f);
}

void DesignerInputTest::closingDuringRenderImage_CancelsItAndReturnsPromptly() {
    // Far more work than a second (3840x2160, 64 samples a pixel), so only a cancel is quick.
    SceneDocument doc = window_->editor()->document();
    doc.render.supersampling = 64;
    QVERIFY(traceViewport(*window_, QSize(128, 72), 4));  // Keeps the viewport's own session cheap.
    window_->editor()->replaceDocument(doc);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("render.png"));
    window_->renderImage(path, 3840, 2160);
    QTest::qWait(500);  // Well into the render.

    // Closing asks first while a render runs (render_job_test.cpp says No too); say Yes.
    int questions = 0;
    setConfirmationHandler([&questions](const QString&, const QString&) {
        ++questions;
        return true;
    });
    QElapsedTimer timer;
    timer.start();
    window_->editor()->undoStack()->setClean();
    const bool closed = window_->close();
    window_.reset();
    setConfirmationHandler({});
    QVERIFY(closed);
    QCOMPARE(questions, 1);
    const qint64 ms = timer.elapsed();
    QVERIFY2(ms < 5000, qPrintable(QStringLiteral("closing took %1 ms").arg(ms)));
    QVERIFY(!QFile::exists(path));  // Cancelled, not finished.
}

QTEST_MAIN(DesignerInputTest)
#include "designer_input_test.moc"
