// Material colours in the designer (issue 29): the Colour / Checker / Image selector is one
// undo step each way and Colour brings the flat colour back; the checker's and the texture's
// fields reach the document; the texture's thumbnail, or the error of a file that cannot be
// read; an image dropped on an object gives it the texture in one undo step without changing
// the objects that shared its material; the texture cache preference reaches the store; an
// image saved again on disk shows after File > Reload Images (or the window's return to the
// front), in the viewport and the thumbnail, without an undo step.
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QImage>
#include <QLabel>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QUrl>
#include <QtTest>
#include <cmath>

#include "display/display_frame.h"
#include "gui_test_support.h"
#include "image/image_io.h"
#include "io/scene_io.h"
#include "panel_fields.h"
#include "panels/color_pattern_editor.h"
#include "panels/image_preview.h"
#include "panels/property_panel.h"
#include "scene/parameters.h"
#include "shell/preferences.h"
#include "texture/texture_store.h"

using namespace rs;
using namespace rs::ui;
using namespace rs::ui::test;

namespace {

/// An 8 x 4 PNG: the left half pure red, the right half pure green.
bool writeRedGreen(const QString& path) {
    QImage image(8, 4, QImage::Format_RGB888);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) image.setPixelColor(x, y, x < 4 ? Qt::red : Qt::green);
    return image.save(path, "PNG");
}

}  // namespace

class TexturesTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();

    void colourMode_EachSwitchIsOneUndoStep_AndColourBringsTheFlatColourBack();
    void checkerFields_ReachTheDocument_AndRefuseWhatTheFormatRefuses();
    void imageMode_ChosenFile_Thumbnail_AndRepeatReachTheDocument();
    void unreadableTexture_ShowsTheErrorInsteadOfAThumbnail();
    void exrThumbnail_IsLinearEncodedToSrgb();
    void thumbnail_IsReadOffTheGuiThread_ThenShown();
    void imageDroppedOnASharedMaterial_MakesItsOwn_InOneUndoStep();
    void imageDroppedOnAnOwnMaterial_TexturesIt_AndEmptySpaceSaysWhere();
    void textureCachePreference_SetsTheStore_AndIsKept();
    void imageSavedAgain_ReloadImagesShowsIt_WithoutAnUndoStep();

private:
    const SceneDocument& doc() { return window_->editor()->document(); }
    const Material& material(const std::string& name) { return *doc().findMaterial(name); }
    int undoCount() { return window_->editor()->undoStack()->count(); }
    void clickObject(const std::string& name);
    QComboBox* modeCombo();
    /// Moves the mode selector one item down (Key_Down) or up, as the keyboard does.
    void stepMode(Qt::Key key);
    /// Steps the selector to Image, choosing `path` in the file dialog it opens.
    void chooseImage(const QString& path);
    /// Drops a file URL of `path` on the main window at viewport point `at`.
    void dropFile(const QString& path, const QPoint& at);
    QPoint framePixelOf(const std::string& name);
    QPoint viewportPointOf(const std::string& name);

    std::unique_ptr<MainWindow> window_;
    QTemporaryDir dir_;
};

void TexturesTest::init() {
    QSettings().remove(QStringLiteral("textures/cacheMegabytes"));
    QVERIFY(dir_.isValid());
    QVERIFY(openRoomWindow(window_));
}

void TexturesTest::cleanup() {
    QSettings().remove(QStringLiteral("textures/cacheMegabytes"));
    TextureStore::shared().setCacheMegabytes(kDefaultTextureCacheMegabytes);
    if (!window_) return;
    window_->editor()->undoStack()->setClean();  // No save prompt on close.
    window_.reset();
}

void TexturesTest::clickObject(const std::string& name) {
    QTest::mouseClick(window_->viewport(), Qt::LeftButton, {}, viewportPointOf(name));
    QCOMPARE(window_->editor()->selection(), idOf(*window_, name));
}

QPoint TexturesTest::viewportPointOf(const std::string& name) {
    const QPoint p = framePixelOf(name);
    return p.x() < 0 ? p : window_->viewport()->widgetPointOf(p.x(), p.y());
}

QPoint TexturesTest::framePixelOf(const std::string& name) {
    // A pixel showing the object (its pixels' centre may show another one in front of it).
    const DisplayFrame& f = *window_->viewport()->frame();
    const ObjectId id = idOf(*window_, name);
    const auto [cx, cy] = pixelOf(f, id);
    if (cx < 0) return {-1, -1};
    int best = -1, bx = 0, by = 0;
    for (int y = 1; y + 1 < f.height; ++y)
        for (int x = 1; x + 1 < f.width; ++x) {
            // All four neighbours too: well inside the object's silhouette.
            if (f.idAt(x, y) != id || f.idAt(x - 1, y) != id || f.idAt(x + 1, y) != id ||
                f.idAt(x, y - 1) != id || f.idAt(x, y + 1) != id)
                continue;
            const int d = (x - cx) * (x - cx) + (y - cy) * (y - cy);
            if (best < 0 || d < best) best = d, bx = x, by = y;
        }
    return best < 0 ? QPoint(-1, -1) : QPoint(bx, by);
}

QComboBox* TexturesTest::modeCombo() {
    return window_->propertyPanel()->findChild<QComboBox*>(QStringLiteral("colorMode"));
}

void TexturesTest::stepMode(Qt::Key key) {
    QComboBox* combo = modeCombo();
    QVERIFY(combo);
    combo->setFocus();
    QTest::keyClick(combo, key);
}

void TexturesTest::chooseImage(const QString& path) {
    bool ran = false;
    QTimer::singleShot(0, this, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        ran = true;
        // Filtered to images, as the task asks.
        QVERIFY2(dialog->nameFilters().join(' ').contains(QStringLiteral("*.exr")),
                 qPrintable(dialog->nameFilters().join(' ')));
        dialog->selectFile(path);
        static_cast<QDialog*>(dialog)->accept();  // QFileDialog makes accept() protected.
    });
    stepMode(Qt::Key_Down);  // Returns when the dialog closes.
    QVERIFY(ran);
}

void TexturesTest::dropFile(const QString& path, const QPoint& at) {
    auto* mime = new QMimeData;
    mime->setUrls({QUrl::fromLocalFile(path)});
    const QPointF inWindow = window_->viewport()->mapTo(window_.get(), at);
    // As a file manager's drag arrives: the enter event makes the window the drop's target.
    QDragEnterEvent enter(inWindow.toPoint(), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(inWindow, Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_.get(), &drop);
    delete mime;
}

void TexturesTest::colourMode_EachSwitchIsOneUndoStep_AndColourBringsTheFlatColourBack() {
    clickObject("chalk ball");
    const Material before = material("chalk");
    QVERIFY(std::holds_alternative<std::monostate>(before.pattern));
    QVERIFY(panelField(*window_, QStringLiteral("Material \""), QStringLiteral("Colour")));

    stepMode(Qt::Key_Down);  // Colour -> Checker
    QCOMPARE(undoCount(), 1);
    const auto* checker = std::get_if<CheckerPattern>(&material("chalk").pattern);
    QVERIFY(checker);
    QVERIFY(checker->even == before.color);  // The first colour keeps the material's hue.
    QCOMPARE(checker->scale, 1.0f);          // scenes/FORMAT.md: the scale defaults to 1.
    QVERIFY(material("chalk").color == before.color);
    // The panel shows the checker's fields and hides the flat colour.
    QVERIFY(panelField(*window_, QStringLiteral("Checker"), QStringLiteral("Colour 1")));
    QVERIFY(panelField(*window_, QStringLiteral("Checker"), QStringLiteral("Colour 2")));
    QVERIFY(panelField(*window_, QStringLiteral("Checker"), QStringLiteral("Cell size")));
    QVERIFY(!panelField(*window_, QStringLiteral("Material \""), QStringLiteral("Colour")));

    stepMode(Qt::Key_Up);  // Checker -> Colour
    QCOMPARE(undoCount(), 2);
    QVERIFY(material("chalk") == before);  // The same flat colour, nothing else changed.
    QVERIFY(panelField(*window_, QStringLiteral("Material \""), QStringLiteral("Colour")));
    QVERIFY(!panelField(*window_, QStringLiteral("Checker"), QStringLiteral("Colour 1")));

    window_->editor()->undoStack()->undo();
    QVERIFY(std::holds_alternative<CheckerPattern>(material("chalk").pattern));
    QCOMPARE(modeCombo()->currentIndex(), 1);
    window_->editor()->undoStack()->undo();
    QVERIFY(material("chalk") == before);
    QCOMPARE(modeCombo()->currentIndex(), 0);
}

void TexturesTest::checkerFields_ReachTheDocument_AndRefuseWhatTheFormatRefuses() {
    clickObject("chalk ball");
    stepMode(Qt::Key_Down);
    QVERIFY(std::holds_alternative<CheckerPattern>(material("chalk").pattern));
    auto* size = qobject_cast<QDoubleSpinBox*>(
        panelField(*window_, QStringLiteral("Checker"), QStringLiteral("Cell size"))
            ->findChild<QDoubleSpinBox*>());
    QVERIFY(size);
    typeInto(size, QStringLiteral("0.25"));
    QCOMPARE(std::get<CheckerPattern>(material("chalk").pattern).scale, 0.25f);
    PropertyPanel* panel = window_->propertyPanel();
    QVERIFY(panel->applyEdit(QStringLiteral("checker"), "odd", Vec3(0.2f, 0.4f, 0.6f)));
    QVERIFY(std::get<CheckerPattern>(material("chalk").pattern).odd == Vec3(0.2f, 0.4f, 0.6f));
    // The colour button shows the new colour after the edit.
    auto* swatch = panelField(*window_, QStringLiteral("Checker"), QStringLiteral("Colour 2"))
                       ->findChild<QPushButton*>(QStringLiteral("colorButton"));
    QVERIFY(swatch);
    QVERIFY2(swatch->text().startsWith(QStringLiteral("0.2, 0.4, 0.6")),
             qPrintable(swatch->text()));
    // A cell of size 0 is refused (FORMAT.md: > 0) and the document keeps 0.25.
    const int steps = undoCount();
    QVERIFY(!panel->applyEdit(QStringLiteral("checker"), "scale", 0.0f));
    QVERIFY(panel->lastError().contains(QStringLiteral("scale")));
    QCOMPARE(std::get<CheckerPattern>(material("chalk").pattern).scale, 0.25f);
    QCOMPARE(undoCount(), steps);
}

void TexturesTest::imageMode_ChosenFile_Thumbnail_AndRepeatReachTheDocument() {
    const QString path = dir_.filePath(QStringLiteral("redgreen.png"));
    QVERIFY(writeRedGreen(path));
    clickObject("chalk ball");
    stepMode(Qt::Key_Down);  // Checker first, then Image: each one step.
    chooseImage(path);
    QCOMPARE(undoCount(), 2);
    const auto* texture = std::get_if<ImageTexture>(&material("chalk").pattern);
    QVERIFY(texture);
    QCOMPARE(QString::fromStdString(texture->image.file), path);
    QCOMPARE(QString::fromStdString(texture->image.resolvedPath), path);
    // Saved beside the image, the scene names it relative to its own folder.
    const std::string saved = serializeScene(doc(), dir_.path().toStdString());
    QVERIFY2(saved.find("\"texture\": \"redgreen.png\"") != std::string::npos, saved.c_str());
    QCOMPARE(texture->scaleU, 1.0f);  // FORMAT.md: scale [1, 1], offset [0, 0] by default.
    QCOMPARE(texture->offsetV, 0.0f);

    auto* preview = window_->propertyPanel()->findChild<ImagePreview*>();
    QVERIFY(preview);
    QVERIFY(previewsRead(*window_));
    QVERIFY2(preview->hasImage(), qPrintable(preview->error()));
    auto* thumb = preview->findChild<QLabel*>(QStringLiteral("textureThumbnail"));
    const QImage shown = thumb->pixmap().toImage();
    // 8 x 4 fitted to the thumbnail's side, aspect kept.
    QCOMPARE(shown.size(), QSize(kTextureThumbnailSide, kTextureThumbnailSide / 2));
    const QColor left = shown.pixelColor(shown.width() / 8, shown.height() / 2);
    const QColor right = shown.pixelColor(shown.width() * 7 / 8, shown.height() / 2);
    QVERIFY2(left.red() > 200 && left.green() < 60, qPrintable(left.name()));
    QVERIFY2(right.green() > 200 && right.red() < 60, qPrintable(right.name()));

    auto* repeat = panelField(*window_, QStringLiteral("Image texture"), QStringLiteral("Repeat U"))
                       ->findChild<QDoubleSpinBox*>();
    QVERIFY(repeat);
    typeInto(repeat, QStringLiteral("3"));
    QCOMPARE(std::get<ImageTexture>(material("chalk").pattern).scaleU, 3.0f);
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("texture"), "offset_v", 0.5f));
    QCOMPARE(std::get<ImageTexture>(material("chalk").pattern).offsetV, 0.5f);
    const int steps = undoCount();
    window_->editor()->undoStack()->undo();
    window_->editor()->undoStack()->undo();
    QCOMPARE(std::get<ImageTexture>(material("chalk").pattern).scaleU, 1.0f);
    QCOMPARE(window_->editor()->undoStack()->index(), steps - 2);
}

void TexturesTest::unreadableTexture_ShowsTheErrorInsteadOfAThumbnail() {
    const QString good = dir_.filePath(QStringLiteral("redgreen.png"));
    QVERIFY(writeRedGreen(good));
    const QString bad = dir_.filePath(QStringLiteral("broken.png"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("this is not a PNG");
    f.close();
    clickObject("chalk ball");
    stepMode(Qt::Key_Down);
    chooseImage(good);
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("texture"), "texture",
                                                bad.toStdString()));
    auto* preview = window_->propertyPanel()->findChild<ImagePreview*>();
    QVERIFY(preview);
    QVERIFY(previewsRead(*window_));
    QVERIFY(!preview->hasImage());
    QVERIFY2(preview->error().contains(QStringLiteral("broken.png")), qPrintable(preview->error()));
    auto* error = preview->findChild<QLabel*>(QStringLiteral("textureError"));
    QVERIFY(error && error->isVisibleTo(preview));

    // The viewport's render says so too, naming the key and the file, and only once: a
    // further edit of the same material does not say it again.
    const auto said = [this] {
        const QString m = window_->statusBar()->currentMessage();
        return m.contains(QStringLiteral("/color/texture")) &&
               m.contains(QStringLiteral("broken.png"));
    };
    QVERIFY2(QTest::qWaitFor(said, 20000), qPrintable(window_->statusBar()->currentMessage()));
    window_->statusBar()->clearMessage();
    QVERIFY(window_->propertyPanel()->applyEdit(QStringLiteral("material"), "diffuse", 0.5f));
    QTest::qWait(500);
    QVERIFY2(!said(), qPrintable(window_->statusBar()->currentMessage()));
}

void TexturesTest::thumbnail_IsReadOffTheGuiThread_ThenShown() {
    // Decoding and scaling a large image takes the reader's thread hundreds of milliseconds
    // (a 4096 x 4096 PNG about half a second): the window must not wait for it.
    const QString path = dir_.filePath(QStringLiteral("wide.png"));
    QImage wide(2048, 1024, QImage::Format_RGB888);
    wide.fill(Qt::blue);
    QVERIFY(wide.save(path, "PNG"));
    clickObject("chalk ball");
    stepMode(Qt::Key_Down);
    chooseImage(path);
    QVERIFY(std::holds_alternative<ImageTexture>(material("chalk").pattern));
    auto* preview = window_->propertyPanel()->findChild<ImagePreview*>();
    QVERIFY(preview);
    // Back from the choice before the file is read: the panel says it is reading it.
    QVERIFY(preview->reading());
    QVERIFY(!preview->hasImage());
    QVERIFY(preview->error().isEmpty());
    auto* note = preview->findChild<QLabel*>(QStringLiteral("textureThumbnailReading"));
    QVERIFY(note && note->isVisibleTo(preview));
    QVERIFY2(note->text().contains(QStringLiteral("wide.png")), qPrintable(note->text()));
    // Then the thumbnail arrives through the event loop, and the note goes.
    QVERIFY(previewsRead(*window_));
    QVERIFY2(preview->hasImage(), qPrintable(preview->error()));
    QVERIFY(!note->isVisibleTo(preview));
    const QImage shown =
        preview->findChild<QLabel*>(QStringLiteral("textureThumbnail"))->pixmap().toImage();
    QCOMPARE(shown.size(), QSize(kTextureThumbnailSide, kTextureThumbnailSide / 2));
    QCOMPARE(shown.pixelColor(shown.width() / 2, shown.height() / 2), QColor(Qt::blue));
}

void TexturesTest::exrThumbnail_IsLinearEncodedToSrgb() {
    // Left half linear 0.2140 (sRGB 0.5: 1.055 * 0.214^(1/2.4) - 0.055), right half 4 (HDR,
    // beyond white): QImageReader cannot read EXR, the thumbnail must still show it.
    ImageRgb image(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            image.pixels[std::size_t(y) * 8 + x] = Color(x < 4 ? 0.2140f : 4.0f);
    const QString path = dir_.filePath(QStringLiteral("grey.exr"));
    std::string error;
    QVERIFY2(writeImage(path.toStdString(), image, ToneMap::Clamp, 0.0f, error), error.c_str());
    clickObject("chalk ball");
    stepMode(Qt::Key_Down);
    chooseImage(path);
    auto* preview = window_->propertyPanel()->findChild<ImagePreview*>();
    QVERIFY(preview);
    QVERIFY(previewsRead(*window_));
    QVERIFY2(preview->hasImage(), qPrintable(preview->error()));
    const QImage shown =
        preview->findChild<QLabel*>(QStringLiteral("textureThumbnail"))->pixmap().toImage();
    const double expected = 255.0 * (1.055 * std::pow(0.2140, 1.0 / 2.4) - 0.055);
    const QColor left = shown.pixelColor(shown.width() / 8, shown.height() / 2);
    const QColor right = shown.pixelColor(shown.width() * 7 / 8, shown.height() / 2);
    QVERIFY2(std::abs(left.red() - expected) <= 2.0 && left.red() == left.blue(),
             qPrintable(QStringLiteral("%1 vs %2").arg(left.red()).arg(expected)));
    QCOMPARE(right.green(), 255);
}

void TexturesTest::imageDroppedOnASharedMaterial_MakesItsOwn_InOneUndoStep() {
    const QString path = dir_.filePath(QStringLiteral("bricks.png"));
    QVERIFY(writeRedGreen(path));
    const ObjectId wall = idOf(*window_, "back wall");
    const Material white = material("white wall");
    QCOMPARE(doc().findObject(idOf(*window_, "ceiling"))->material, std::string("white wall"));
    const std::size_t materials = doc().materials.size();
    const QPoint at = viewportPointOf("back wall");
    QVERIFY(at.x() >= 0);

    dropFile(path, at);
    QCOMPARE(undoCount(), 1);
    const std::string name = doc().findObject(wall)->material;
    QVERIFY2(name != "white wall", name.c_str());
    QCOMPARE(doc().materials.size(), materials + 1);
    const Material& own = material(name);
    const auto* texture = std::get_if<ImageTexture>(&own.pattern);
    QVERIFY(texture);
    QCOMPARE(QString::fromStdString(texture->image.source()), path);
    QCOMPARE(own.diffuse, white.diffuse);  // The old material's coefficients, copied.
    QVERIFY(own.color == white.color);
    // The objects that shared it keep it, unchanged.
    QVERIFY(material("white wall") == white);
    QCOMPARE(doc().findObject(idOf(*window_, "ceiling"))->material, std::string("white wall"));
    QCOMPARE(doc().findObject(idOf(*window_, "front wall"))->material, std::string("white wall"));
    const QString said = window_->statusBar()->currentMessage();
    QVERIFY2(
        said.contains(QStringLiteral("bricks.png")) && said.contains(QStringLiteral("back wall")),
        qPrintable(said));

    window_->editor()->undoStack()->undo();
    QCOMPARE(doc().findObject(wall)->material, std::string("white wall"));
    QCOMPARE(doc().materials.size(), materials);
}

void TexturesTest::imageDroppedOnAnOwnMaterial_TexturesIt_AndEmptySpaceSaysWhere() {
    const QString path = dir_.filePath(QStringLiteral("chalky.png"));
    QVERIFY(writeRedGreen(path));
    const std::size_t materials = doc().materials.size();
    dropFile(path, viewportPointOf("chalk ball"));
    QCOMPARE(undoCount(), 1);
    QCOMPARE(doc().findObject(idOf(*window_, "chalk ball"))->material, std::string("chalk"));
    QCOMPARE(doc().materials.size(), materials);
    const auto* texture = std::get_if<ImageTexture>(&material("chalk").pattern);
    QVERIFY(texture);
    QCOMPARE(QString::fromStdString(texture->image.source()), path);

    // Outside every object (here, outside the viewport): nothing changes, the bar says where.
    dropFile(path, QPoint(-20, -20));
    QCOMPARE(undoCount(), 1);
    const QString said = window_->statusBar()->currentMessage();
    QVERIFY2(said.contains(QStringLiteral("on an object")), qPrintable(said));
}

void TexturesTest::textureCachePreference_SetsTheStore_AndIsKept() {
    TextureStore::shared().setCacheMegabytes(100.0f);  // Not the default: load must set it.
    QCOMPARE(loadPreferences().textureCacheMegabytes, 256);
    QCOMPARE(TextureStore::shared().cacheMegabytes(), 256.0f);
    PreferencesDialog* dialog = window_->showPreferences();
    QVERIFY(dialog);
    auto* spin = dialog->findChild<QSpinBox*>(QStringLiteral("textureCacheMegabytes"));
    QVERIFY(spin);
    QCOMPARE(spin->value(), 256);
    spin->setValue(512);
    QCOMPARE(TextureStore::shared().cacheMegabytes(), 512.0f);
    QCOMPARE(QSettings().value(QStringLiteral("textures/cacheMegabytes")).toInt(), 512);
    dialog->close();
    // At the next start the stored value is applied.
    TextureStore::shared().setCacheMegabytes(100.0f);
    QCOMPARE(loadPreferences().textureCacheMegabytes, 512);
    QCOMPARE(TextureStore::shared().cacheMegabytes(), 512.0f);
}

void TexturesTest::imageSavedAgain_ReloadImagesShowsIt_WithoutAnUndoStep() {
    const QString path = dir_.filePath(QStringLiteral("paint.png"));
    QVERIFY(writeFlat(path, Qt::red, -20));
    clickObject("chalk ball");
    stepMode(Qt::Key_Down);
    chooseImage(path);
    const int steps = undoCount();
    // The ball's colour in the viewport's frame.
    const QPoint at = framePixelOf("chalk ball");
    QVERIFY(at.x() >= 0);
    const auto shown = [&] {
        settle(*window_);
        return toneMappedImage(*window_->viewport()->frame()).pixelColor(at);
    };
    const QColor red = shown();
    QVERIFY2(red.red() > 2 * red.green(), qPrintable(red.name()));
    QVERIFY(previewsRead(*window_));
    auto* thumb = window_->propertyPanel()->findChild<QLabel*>(QStringLiteral("textureThumbnail"));
    QVERIFY(thumb);
    QCOMPARE(thumb->pixmap().toImage().pixelColor(1, 1), QColor(Qt::red));

    // Saved again in green, as a paint program would while the designer is open.
    QVERIFY(writeFlat(path, Qt::green, -10));
    auto* reload = window_->findChild<QAction*>(QStringLiteral("reloadImages"));
    QVERIFY(reload);
    reload->trigger();
    const QColor green = shown();
    QVERIFY2(green.green() > 2 * green.red(), qPrintable(green.name()));
    QVERIFY(previewsRead(*window_));
    // Only what sees the ball was traced again.
    const DisplayFrame& f = *window_->viewport()->frame();
    const std::size_t marked = renderSession(*window_).stats().lastDirtyPixels;
    QVERIFY2(marked > 0 && marked < std::size_t(f.width) * std::size_t(f.height) / 3,
             qPrintable(QString::number(marked)));
    thumb = window_->propertyPanel()->findChild<QLabel*>(QStringLiteral("textureThumbnail"));
    QVERIFY(thumb);
    QCOMPARE(thumb->pixmap().toImage().pixelColor(1, 1), QColor(Qt::green));
    QCOMPARE(undoCount(), steps);
    QVERIFY(window_->editor()->undoStack()->canUndo());
}

QTEST_MAIN(TexturesTest)
#include "textures_test.moc"
