// Material previews in the Materials dock (issue 29): each material's icon is a sphere traced
// in the background over a checkered backdrop; only materials whose content changed are
// traced again, rapid edits render only the latest content, and a move renders nothing.
#include "panels/material_preview.h"

#include <QApplication>
#include <QIcon>
#include <QLineEdit>
#include <QListWidget>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <variant>

#include "document/scene_editor.h"
#include "document/scene_edits.h"
#include "panels/material_list.h"

using namespace rs;
using namespace rs::ui;

namespace {

Material diffuse(const char* name, Color color) {
    Material m;
    m.name = name;
    m.color = color;
    return m;
}

/// The sRGB encoding of a linear value in [0, 1], as 8 bits (IEC 61966-2-1).
int srgb8(float linear) {
    const double v =
        linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    return int(std::lround(v * 255.0));
}

/// Mean of the pixels within `radius` of (cx, cy).
QVector3D meanAround(const QImage& image, double cx, double cy, double radius) {
    QVector3D sum;
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) <= radius) {
                const QColor c = image.pixelColor(x, y);
                sum += QVector3D(c.red(), c.green(), c.blue());
                ++n;
            }
    return n ? sum / float(n) : QVector3D(-1, -1, -1);
}

double luminance(QRgb c) {
    return 0.2126 * qRed(c) + 0.7152 * qGreen(c) + 0.0722 * qBlue(c);
}

QString describe(const QVector3D& v) {
    return QStringLiteral("(%1, %2, %3)").arg(v.x()).arg(v.y()).arg(v.z());
}

}  // namespace

class MaterialPreviewTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void diffuseRed_IsARedSphereLitFromItsLight_OverACheckeredFloor();
    void mirrorAndGlass_DifferFromDiffuseOfTheSameColour();
    void colourEdit_ShowsTheSwatchAtOnce_ThenRendersThatMaterialOnly();
    void rapidEdits_RenderOnlyTheLatestContent();
    void movingAnObject_OrRenamingAMaterial_RendersNothing();
    void previewArrivingDuringAnInPlaceRename_KeepsWhatIsTyped();
    void environmentEdits_RenderEveryMaterialOnce_AndTexturesAreTraced();
    void textureFileResavedOnDisk_IsANewPreview();

private:
    /// The icon of material `name` as the list draws it, at its full resolution.
    QImage icon(const QString& name) const;
    bool waitIdle() const;
    /// Edits the document through the editor, as the property panel does.
    void editMaterial(const char* name, const std::function<void(Material&)>& change);
    int renders() const { return list_->previews()->rendersStarted(); }

    std::unique_ptr<SceneEditor> editor_;
    std::unique_ptr<MaterialList> list_;
};

void MaterialPreviewTest::init() {
    SceneDocument doc;
    doc.materials.push_back(diffuse("red", Color(0.8f, 0.04f, 0.04f)));
    doc.materials.push_back(diffuse("blue", Color(0.05f, 0.1f, 0.8f)));
    doc.materials.push_back(diffuse("grey", Color(0.9f, 0.9f, 0.9f)));
    Material mirror = diffuse("mirror", Color(0.9f, 0.9f, 0.9f));
    mirror.diffuse = 0.05f;
    mirror.reflectivity = 0.9f;
    doc.materials.push_back(mirror);
    Material glass = diffuse("glass", Color(0.9f, 0.9f, 0.9f));
    glass.diffuse = 0.0f;
    glass.transparency = 0.9f;
    glass.ior = 1.5f;
    doc.materials.push_back(glass);
    Object ball;
    ball.name = "ball";
    ball.material = "red";
    ball.geometry = SphereGeometry{Vec3(0.0f), 1.0f};
    doc.addObject(ball);
    editor_ = std::make_unique<SceneEditor>();
    editor_->resetDocument(doc, QString());
    list_ = std::make_unique<MaterialList>(editor_.get());
    list_->resize(240, 400);
    list_->show();
    QVERIFY(waitIdle());
}

void MaterialPreviewTest::cleanup() {
    list_.reset();  // Waits for a render in flight.
    editor_.reset();
}

QImage MaterialPreviewTest::icon(const QString& name) const {
    const QList<QListWidgetItem*> items = list_->list()->findItems(name, Qt::MatchExactly);
    if (items.size() != 1) return {};
    const QIcon i = items.front()->icon();
    if (i.availableSizes().isEmpty()) return {};
    return i.pixmap(i.availableSizes().front()).toImage().convertToFormat(QImage::Format_ARGB32);
}

bool MaterialPreviewTest::waitIdle() const {
    return QTest::qWaitFor([this] { return !list_->previews()->busy(); }, 60000);
}

void MaterialPreviewTest::editMaterial(const char* name,
                                       const std::function<void(Material&)>& change) {
    SceneDocument doc = editor_->document();
    for (Material& m : doc.materials)
        if (m.name == name) change(m);
    editor_->edit(QStringLiteral("edit"), std::move(doc), MergeKind::Property,
                  QString::fromLatin1(name));
}

void MaterialPreviewTest::diffuseRed_IsARedSphereLitFromItsLight_OverACheckeredFloor() {
    const QImage image = icon(QStringLiteral("red"));
    QVERIFY(!image.isNull());
    const int side = image.width();
    QCOMPARE(image.height(), side);
    QVERIFY2(side >= MaterialList::kIconSide, qPrintable(QString::number(side)));
    // The centre of the sphere: red well above green and blue, and not black.
    const QVector3D centre = meanAround(image, side / 2.0, side / 2.0, side / 12.0);
    QVERIFY2(centre.x() > 60 && centre.x() > 3 * centre.y() && centre.x() > 3 * centre.z(),
             qPrintable(describe(centre)));
    // Lit from above-left in front: the upper-left of the ball is brighter than its lower-right.
    const double r = side * 0.2;
    const QVector3D upperLeft = meanAround(image, side / 2.0 - r, side / 2.0 - r, side / 20.0);
    const QVector3D lowerRight = meanAround(image, side / 2.0 + r, side / 2.0 + r, side / 20.0);
    QVERIFY2(upperLeft.x() > lowerRight.x() + 20,
             qPrintable(describe(upperLeft) + QStringLiteral(" vs ") + describe(lowerRight)));
    // Traced, not a swatch: the corners are opaque and the floor along the bottom row shows
    // the checker's light and dark cells.
    QCOMPARE(qAlpha(image.pixel(0, 0)), 255);
    QCOMPARE(qAlpha(image.pixel(side - 1, side - 1)), 255);
    double lo = 255, hi = 0;
    for (int x = 0; x < side; ++x) {
        const double l = luminance(image.pixel(x, side - 2));
        lo = std::min(lo, l), hi = std::max(hi, l);
    }
    QVERIFY2(hi - lo > 60 && hi - lo < 256, qPrintable(QStringLiteral("%1..%2").arg(lo).arg(hi)));
}

void MaterialPreviewTest::mirrorAndGlass_DifferFromDiffuseOfTheSameColour() {
    const QImage grey = icon(QStringLiteral("grey"));
    QVERIFY(!grey.isNull());
    const int side = grey.width();
    // Mean absolute difference over the ball (a disc of a third of the image's side).
    auto difference = [&](const QImage& other) {
        double sum = 0;
        int n = 0;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                if (std::hypot(x + 0.5 - side / 2.0, y + 0.5 - side / 2.0) < side / 3.0) {
                    const QRgb a = grey.pixel(x, y), b = other.pixel(x, y);
                    sum += std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) +
                           std::abs(qBlue(a) - qBlue(b));
                    n += 3;
                }
        return sum / n;
    };
    const QImage mirror = icon(QStringLiteral("mirror"));
    const QImage glass = icon(QStringLiteral("glass"));
    QCOMPARE(mirror.size(), grey.size());
    QCOMPARE(glass.size(), grey.size());
    const double dm = difference(mirror), dg = difference(glass);
    QVERIFY2(dm > 15 && dm < 255, qPrintable(QString::number(dm)));
    QVERIFY2(dg > 15 && dg < 255, qPrintable(QString::number(dg)));
    // And the grey one against itself: 0, so the measure can tell.
    QCOMPARE(difference(grey), 0.0);
}

void MaterialPreviewTest::colourEdit_ShowsTheSwatchAtOnce_ThenRendersThatMaterialOnly() {
    QSignalSpy ready(list_->previews(), &MaterialPreviews::previewReady);
    const int before = renders();
    editMaterial("blue", [](Material& m) { m.color = Color(0.05f, 0.7f, 0.05f); });
    // No event has run yet, so no render can have come back: the swatch of the new colour,
    // a disc on a transparent ground.
    const QImage swatch = icon(QStringLiteral("blue"));
    QVERIFY(!swatch.isNull());
    const int side = swatch.width();
    QCOMPARE(qAlpha(swatch.pixel(0, 0)), 0);
    const QColor c = swatch.pixelColor(side / 2, side / 2);
    QVERIFY2(std::abs(c.red() - srgb8(0.05f)) <= 1 && std::abs(c.green() - srgb8(0.7f)) <= 1 &&
                 std::abs(c.blue() - srgb8(0.05f)) <= 1,
             qPrintable(c.name()));

    QVERIFY(waitIdle());
    QCOMPARE(renders(), before + 1);
    QCOMPARE(ready.size(), 1);
    QCOMPARE(ready.front().at(0).toString(), QStringLiteral("blue"));
    const QImage preview = icon(QStringLiteral("blue"));
    QCOMPARE(qAlpha(preview.pixel(0, 0)), 255);
    const QVector3D centre = meanAround(preview, side / 2.0, side / 2.0, side / 12.0);
    QVERIFY2(centre.y() > 60 && centre.y() > 3 * centre.x() && centre.y() > 3 * centre.z(),
             qPrintable(describe(centre)));
}

void MaterialPreviewTest::rapidEdits_RenderOnlyTheLatestContent() {
    QSignalSpy ready(list_->previews(), &MaterialPreviews::previewReady);
    const int before = renders();
    // A slider sweep: red-ish steps, then green last. Events run between some of them, as a
    // drag's do, so a render is in flight when the next edit lands.
    for (int i = 0; i < 8; ++i) {
        editMaterial("blue", [i](Material& m) { m.color = Color(0.3f + 0.07f * i, 0.02f, 0.02f); });
        if (i % 3 == 0) QCoreApplication::processEvents();
    }
    editMaterial("blue", [](Material& m) { m.color = Color(0.02f, 0.75f, 0.02f); });
    QVERIFY(waitIdle());
    // Each run of edits between event loops asks for at most one render, and every render
    // superseded before it came back was dropped: only the last content reached the list.
    QVERIFY2(renders() - before >= 1 && renders() - before <= 5,
             qPrintable(QString::number(renders() - before)));
    QVERIFY(ready.size() >= 1);
    for (const QList<QVariant>& signal : ready)
        QCOMPARE(signal.at(0).toString(), QStringLiteral("blue"));
    const QString lastKey = ready.back().at(1).toString();
    const Material* last = editor_->document().findMaterial("blue");
    QVERIFY(last);
    const QImage preview = icon(QStringLiteral("blue"));
    QCOMPARE(lastKey, QString::fromStdString(materialPreviewKey(
                          *last, editor_->document().environment, preview.width())));
    const int side = preview.width();
    const QVector3D centre = meanAround(preview, side / 2.0, side / 2.0, side / 12.0);
    QVERIFY2(centre.y() > 60 && centre.y() > 3 * centre.x(), qPrintable(describe(centre)));
}

void MaterialPreviewTest::movingAnObject_OrRenamingAMaterial_RendersNothing() {
    QSignalSpy ready(list_->previews(), &MaterialPreviews::previewReady);
    const int before = renders();
    const QImage red = icon(QStringLiteral("red"));
    for (int i = 1; i <= 10; ++i) {
        SceneDocument doc = editor_->document();
        doc.objects.front().transform.translate = Vec3(0.1f * i, 0.0f, 0.0f);
        editor_->edit(QStringLiteral("Move"), std::move(doc), MergeKind::Drag, QStringLiteral("g"));
        QCoreApplication::processEvents();
    }
    QVERIFY(!list_->previews()->busy());
    QCOMPARE(renders(), before);

    // A rename keeps the content, so the picture comes from the cache.
    SceneDocument doc = editor_->document();
    QVERIFY(rs::ui::renameMaterial(doc, "red", "crimson").empty());
    editor_->edit(QStringLiteral("Rename"), std::move(doc));
    QCoreApplication::processEvents();
    QVERIFY(!list_->previews()->busy());
    QCOMPARE(renders(), before);
    QCOMPARE(ready.size(), 0);
    QCOMPARE(icon(QStringLiteral("crimson")), red);
}

void MaterialPreviewTest::previewArrivingDuringAnInPlaceRename_KeepsWhatIsTyped() {
    QSignalSpy ready(list_->previews(), &MaterialPreviews::previewReady);
    QVERIFY(list_->setCurrent("blue"));
    list_->renameMaterial();
    auto* field = list_->list()->findChild<QLineEdit*>();
    QVERIFY(field);
    field->setText(QStringLiteral("navy"));
    // The colour changes meanwhile (an undo, a script): its swatch and then its preview come
    // while the name is being typed.
    editMaterial("blue", [](Material& m) { m.color = Color(0.05f, 0.7f, 0.05f); });
    QVERIFY(waitIdle());
    QTRY_COMPARE(ready.size(), 1);
    QCOMPARE(field->text(), QStringLiteral("navy"));
    QTest::keyClick(field, Qt::Key_Return);
    QTRY_VERIFY(editor_->document().findMaterial("navy"));
    // Once the editor has closed the item shows the new colour's preview.
    QTRY_VERIFY(!icon(QStringLiteral("navy")).isNull());
    const QImage preview = icon(QStringLiteral("navy"));
    const int side = preview.width();
    QCOMPARE(qAlpha(preview.pixel(0, 0)), 255);
    const QVector3D centre = meanAround(preview, side / 2.0, side / 2.0, side / 12.0);
    QVERIFY2(centre.y() > 60 && centre.y() > 3 * centre.x(), qPrintable(describe(centre)));
}

void MaterialPreviewTest::environmentEdits_RenderEveryMaterialOnce_AndTexturesAreTraced() {
    const QImage greyBefore = icon(QStringLiteral("grey"));
    const int before = renders();
    SceneDocument doc = editor_->document();
    Material tiles = diffuse("tiles", Color(0.8f, 0.8f, 0.8f));
    ImageTexture texture;
    texture.image.file = RAYSTUDIO_SCENES_DIR "/textures/tiles.png";
    tiles.pattern = texture;
    doc.materials.push_back(tiles);
    doc.environment.image.file = RAYSTUDIO_SCENES_DIR "/textures/sky.hdr";
    editor_->edit(QStringLiteral("Sky and tiles"), std::move(doc));
    QVERIFY(waitIdle());
    // Six materials, each once: the sky is part of every preview.
    QCOMPARE(renders() - before, 6);
    const QImage grey = icon(QStringLiteral("grey"));
    const QImage textured = icon(QStringLiteral("tiles"));
    QCOMPARE(textured.size(), grey.size());
    QVERIFY(grey != greyBefore);  // The sky in place of the wall.
    const int side = grey.width();
    double sum = 0;
    int n = 0;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            if (std::hypot(x + 0.5 - side / 2.0, y + 0.5 - side / 2.0) < side / 3.0) {
                const QRgb a = grey.pixel(x, y), b = textured.pixel(x, y);
                sum += std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) +
                       std::abs(qBlue(a) - qBlue(b));
                n += 3;
            }
    QVERIFY2(sum / n > 15 && sum / n < 255, qPrintable(QString::number(sum / n)));

    // Turning the sky traces every preview again, once each.
    const int turned = renders();
    doc = editor_->document();
    doc.environment.rotation = 90.0f;
    editor_->edit(QStringLiteral("Turn the sky"), std::move(doc));
    QVERIFY(waitIdle());
    QCOMPARE(renders() - turned, 6);
}

void MaterialPreviewTest::textureFileResavedOnDisk_IsANewPreview() {
    // A texture painted red, previewed; then re-saved green in an image editor. Going back to
    // the same fields must not bring back the red preview of the old file.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("paint.png"));
    QImage paint(16, 16, QImage::Format_RGB888);
    paint.fill(QColor(220, 20, 20));
    QVERIFY(paint.save(path));
    SceneDocument doc = editor_->document();
    Material painted = diffuse("painted", Color(0.8f, 0.8f, 0.8f));
    ImageTexture texture;
    texture.image.file = path.toStdString();
    painted.pattern = texture;
    doc.materials.push_back(painted);
    editor_->edit(QStringLiteral("Painted"), std::move(doc));
    QVERIFY(waitIdle());
    const int side = icon(QStringLiteral("painted")).width();
    const QVector3D red =
        meanAround(icon(QStringLiteral("painted")), side / 2.0, side / 2.0, side / 12.0);
    QVERIFY2(red.x() > 2 * red.y(), qPrintable(describe(red)));

    paint.fill(QColor(20, 200, 20));
    QVERIFY(paint.save(path));
    const auto later =
        std::filesystem::last_write_time(path.toStdString()) + std::chrono::seconds(2);
    std::filesystem::last_write_time(path.toStdString(), later);
    const auto scale = [this](float s) {
        editMaterial("painted", [s](Material& m) { std::get<ImageTexture>(m.pattern).scaleU = s; });
        QVERIFY(waitIdle());
    };
    scale(2.0f);
    scale(1.0f);
    const QVector3D green =
        meanAround(icon(QStringLiteral("painted")), side / 2.0, side / 2.0, side / 12.0);
    QVERIFY2(green.y() > 2 * green.x(), qPrintable(describe(green)));
}

QTEST_MAIN(MaterialPreviewTest)
#include "material_preview_test.moc"
