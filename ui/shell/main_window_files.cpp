// MainWindow file handling (new, open, save, recent, drop, import, export) and scene edits.
#include <QDialog>
#include <QDialogButtonBox>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QMessageBox>
#include <QMimeData>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <algorithm>
#include <cstdio>
#include <set>
#include <string>

#include "adapter/session_controller.h"
#include "display/display_frame.h"
#include "document/color_pattern_edits.h"
#include "document/placement.h"
#include "document/scene_editor.h"
#include "document/scene_file_writer.h"
#include "document/texture_drop.h"
#include "image/image_io.h"
#include "integrator/cost_estimate.h"
#include "io/asset_looks.h"
#include "io/scene_io.h"
#include "jobs/background_jobs.h"
#include "jobs/cluster_submit_dialog.h"
#include "jobs/render_queue.h"
#include "panels/dialog_folders.h"
#include "panels/outliner_view.h"
#include "scene/parameters.h"
#include "shell/autosave.h"
#include "shell/error_reporter.h"
#include "shell/imported_images.h"
#include "shell/main_window.h"
#include "shell/pass_status.h"
#include "shell/render_jobs.h"
#include "shell/responsive_wait.h"
#include "shell/user_confirmation.h"
#include "snapshot/compiled_scene.h"
#include "viewport/viewport.h"

namespace rs::ui {

namespace {
const QString kSceneFilter = QObject::tr("RayStudio scenes (*.scene.json *.json)");
const QString kMeshFilter = QObject::tr(
    "3D models (*.obj *.ply *.stl *.gltf *.glb *.fbx *.dae *.3ds *.off);;All files (*)");
const QString kImageFilter = QObject::tr(
    "PNG (*.png);;JPEG (*.jpg *.jpeg);;TIFF (*.tif *.tiff);;OpenEXR (*.exr);;Radiance HDR (*.hdr)");

bool isSceneFile(const QString& path) {
    return path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive);
}
}  // namespace

bool MainWindow::maybeSave() {
    if (editor_->undoStack()->isClean()) return true;
    const auto answer =
        QMessageBox::warning(this, tr("RayStudio"),
                             tr("The scene has been modified.\nDo you want to save your changes?"),
                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::newFile() {
    if (!maybeSave()) return;
    SceneDocument doc;
    doc.camera.position = Vec3(0.0f, 1.5f, 5.0f);
    doc.camera.target = Vec3(0.0f, 0.5f, 0.0f);
    Object floor;
    floor.name = "floor";
    floor.geometry = PlaneGeometry{};
    doc.addObject(std::move(floor));
    Light key;
    key.name = "key light";
    key.position = Vec3(2.0f, 5.0f, 3.0f);
    doc.addLight(std::move(key));
    editor_->resetDocument(std::move(doc), {});
}

void MainWindow::open() {
    if (!maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Scene"), dialogFolder(FileKind::Scene, editor_->filePath()), kSceneFilter);
    rememberDialogFolder(FileKind::Scene, path);
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::openFile(const QString& path) {
    const std::string file = path.toStdString();
    SceneLoadResult result;
    if (QFileInfo(path).size() >= kResponsiveFileBytes) {
        statusBar()->showMessage(tr("Opening %1…").arg(path));
        result = runWhileResponsive([&file] { return loadScene(file); });
        statusBar()->clearMessage();
    } else {
        result = loadScene(file);
    }
    if (!result.ok()) {
        reportError(this, tr("Cannot open scene"),
                    tr("%1 could not be opened:\n\n%2")
                        .arg(path, QString::fromStdString(result.errorText())));
        return false;
    }
    anchorSunGlyphs(result.document);
    std::set<std::string> warned;
    for (const SceneError& w : result.warnings) warned.insert(w.pointer);
    passStatus_->imageProblemsSaid(std::move(warned));
    editor_->resetDocument(std::move(result.document), QFileInfo(path).absoluteFilePath());
    addRecentFile(QFileInfo(path).absoluteFilePath());
    if (result.warnings.empty()) {
        statusBar()->showMessage(tr("Opened %1").arg(path), 3000);
        return true;
    }
    // Images that cannot be read: the scene is usable, the image shows as the missing pattern
    // and is saved back as written. Said without a dialog; the details go to stderr.
    for (const SceneError& w : result.warnings)
        std::fprintf(stderr, "%s (warning)\n", w.toString().c_str());
    statusBar()->showMessage(
        tr("Opened %1; %n image(s) could not be read and show as the missing pattern: %2", "",
           int(result.warnings.size()))
            .arg(path, QString::fromStdString(result.warnings.front().toString())),
        15000);
    return true;
}

bool MainWindow::save() {
    return editor_->filePath().isEmpty() ? saveAs() : saveFile(editor_->filePath());
}

bool MainWindow::saveAs() {
    const QString start =
        editor_->filePath().isEmpty() ? dialogFolder(FileKind::Scene, {}) : editor_->filePath();
    QString path = QFileDialog::getSaveFileName(this, tr("Save Scene"), start, kSceneFilter);
    if (path.isEmpty()) return false;
    rememberDialogFolder(FileKind::Scene, path);
    if (!isSceneFile(path)) path += QStringLiteral(".scene.json");
    return saveFile(path);
}

bool MainWindow::saveFile(const QString& path) {
    const QFileInfo info(path);
    QString error;
    // The document as it is now; a large one is written while the window keeps painting.
    SceneDocument doc = editor_->document();
    // Images that imports wrote before the scene had a file go with it now.
    const MovedImages moved =
        moveImportedImages(doc, importedImageFolder(QString()), info.absolutePath());
    bool written;
    if (doc.objects.size() >= kResponsiveObjects) {
        statusBar()->showMessage(tr("Saving %1…").arg(path));
        written = runWhileResponsive([&] { return writeSceneFile(path, doc, error); });
        statusBar()->clearMessage();
    } else {
        written = writeSceneFile(path, doc, error);
    }
    if (!written) {
        reportError(this, tr("Cannot save scene"),
                    tr("%1 could not be written:\n%2").arg(path, error));
        return false;
    }
    if (!moved.copied.isEmpty()) editor_->replaceDocument(doc);  // what the file says now
    for (const QString& note : moved.notes)
        std::fprintf(stderr, "raystudio: %s\n", qPrintable(note));
    if (!moved.notes.isEmpty())
        reportError(this, tr("Saved %1").arg(path), moved.notes.join(QLatin1Char('\n')));
    editor_->undoStack()->setClean();
    autosave_->discard();  // The file holds every change now.
    editor_->setFilePath(info.absoluteFilePath());
    addRecentFile(info.absoluteFilePath());
    statusBar()->showMessage(tr("Saved %1").arg(path), 3000);
    return true;
}

void MainWindow::setRenderSize(int width, int height) {
    SceneDocument doc = editor_->document();
    doc.render.width = width;
    doc.render.height = height;
    editor_->replaceDocument(std::move(doc));
}

void MainWindow::importMeshDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import"), dialogFolder(FileKind::Mesh, editor_->filePath()), kMeshFilter);
    rememberDialogFolder(FileKind::Mesh, path);
    if (!path.isEmpty()) importMesh(path);
}

/// Where an asset's embedded images are written: the scene's folder once it has a file,
/// else a folder of the designer's own (a later Save As keeps referring to them there).
std::size_t MainWindow::adoptAssetCameras(SceneDocument& doc, ObjectId id,
                                          const AssetContent& asset, const QString& name) {
    if (asset.views.empty()) return 0;
    const QString first = QString::fromStdString(asset.views[0].name);
    const QString text = asset.views.size() == 1 ? tr("%1 brings camera \"%2\".").arg(name, first)
                                                 : tr("%1 brings %2 cameras, the first \"%3\".")
                                                       .arg(name)
                                                       .arg(asset.views.size())
                                                       .arg(first);
    const int choice = choose(this, tr("Import %1").arg(name),
                              text + tr(" Look through it (it becomes the scene camera; all "
                                        "become view bookmarks), keep them as view bookmarks "
                                        "(View > Bookmarks), or leave them out?"),
                              {tr("Look Through It"), tr("Keep as Bookmarks"), tr("Leave Out")});
    if (choice != 0 && choice != 1) return 0;
    const std::vector<std::string> added = adoptAssetViews(doc, id, asset);
    // The asset's first camera as the scene's, in the same undo step as the import.
    if (choice == 0 && !added.empty()) doc.camera = doc.findView(added.front())->camera;
    return added.size();
}

void MainWindow::importMesh(const QString& path, std::optional<QPoint> at) {
    importMeshAsync(this, path, true, [this, path, at](const MeshLoadResult& r) {
        if (!r.ok()) {
            reportError(this, tr("Cannot import mesh"), QString::fromStdString(r.error));
            return;
        }
        SceneDocument doc = editor_->document();
        const Placement place = placementAt(at);
        const ObjectId id =
            addMesh(doc, QFileInfo(path).absoluteFilePath().toStdString(), r.mesh, place.point);
        // A mesh at its file's own size can swallow the view (a 150-unit spider) or vanish
        // in it: scale it to fit, and say so; Transform -> Scale in Properties edits it.
        const float distance = at ? place.distance : fallbackDistance(viewport_->viewCamera());
        const float factor = fitScale(r.mesh->bounds(), viewport_->viewCamera(), distance);
        doc.findObject(id)->transform.scale = Vec3(factor);
        // Dropped on a point: there; from the menu: in front of the view, on the floor.
        if (at)
            placeNew(doc, id, place);
        else
            placeNewInView(doc, id);
        const AdoptedLooks looks =
            r.asset ? adoptAssetLooks(doc, id, *r.asset, QFileInfo(path).fileName().toStdString(),
                                      importedImageFolder(editor_->filePath()).toStdString())
                    : AdoptedLooks{};
        const std::size_t lights =
            r.asset ? adoptAssetLights(doc, id, *r.asset).size() : std::size_t(0);
        const QString name = QString::fromStdString(doc.findObject(id)->name);
        const std::size_t views = r.asset ? adoptAssetCameras(doc, id, *r.asset, name) : 0;
        editor_->edit(tr("Import %1").arg(name), std::move(doc));
        editor_->setSelection(id);
        QString said = tr("Imported %1").arg(name);
        if (!looks.materials.empty())
            said += looks.materials.size() == 1
                        ? tr(" with 1 material")
                        : tr(" with %1 materials").arg(looks.materials.size());
        if (lights > 0) said += lights == 1 ? tr(" and 1 light") : tr(" and %1 lights").arg(lights);
        if (views > 0)
            said += views == 1 ? tr(", its camera a view bookmark")
                               : tr(", its %1 cameras view bookmarks").arg(views);
        if (factor != 1.0f)
            said += tr(", scaled by %1 to fit the view (Properties: Transform, Scale)")
                        .arg(double(factor), 0, 'g', 3);
        statusBar()->showMessage(said, 10000);
        std::vector<std::string> notes = looks.notes;
        if (r.asset)
            for (const std::string& note : r.asset->lightNotes)
                notes.push_back("asset \"" + QFileInfo(path).fileName().toStdString() +
                                "\": " + note);
        if (!notes.empty()) {
            QStringList lines;
            for (const std::string& note : notes) {
                std::fprintf(stderr, "raystudio: %s\n", note.c_str());
                lines << QString::fromStdString(note);
            }
            reportError(this, tr("Imported %1: what its materials could not keep").arg(name),
                        lines.join('\n'));
        }
    });
}

bool MainWindow::exportFrame(const QString& path) {
    const auto frame = viewport_->frame();
    if (!frame || frame->empty()) return false;
    if (frame->color.size() != std::size_t(frame->width) * std::size_t(frame->height)) return false;
    // Through the scene camera, only what lies inside its output frame (the rest is the
    // dimmed margin around it).
    QRect keep(0, 0, frame->width, frame->height);
    const ViewProjection view = viewport_->projection();
    if (viewport_->throughSceneCamera() && view.valid()) {
        const QRectF image(view.imageRect()), output = view.outputRect();
        const double sx = frame->width / image.width(), sy = frame->height / image.height();
        keep = QRect(QPoint(int(std::lround((output.left() - image.left()) * sx)),
                            int(std::lround((output.top() - image.top()) * sy))),
                     QSize(int(std::lround(output.width() * sx)),
                           int(std::lround(output.height() * sy)))) &
               keep;
        if (keep.isEmpty()) keep = QRect(0, 0, frame->width, frame->height);
    }
    ImageRgb image = ImageRgb::uninitialized(keep.width(), keep.height());
    for (int y = 0; y < keep.height(); ++y) {
        const auto row = frame->color.begin() +
                         std::ptrdiff_t(std::size_t(keep.top() + y) * std::size_t(frame->width) +
                                        std::size_t(keep.left()));
        std::copy(
            row, row + keep.width(),
            image.pixels.begin() + std::ptrdiff_t(std::size_t(y) * std::size_t(keep.width())));
    }
    std::string error;
    if (!writeImage(path.toStdString(), image, frame->tonemap, frame->exposure, error)) {
        reportError(this, tr("Cannot export image"), QString::fromStdString(error));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1 (%2x%3, the viewport's frame; Render Image renders "
                                "%4x%5)")
                                 .arg(path)
                                 .arg(keep.width())
                                 .arg(keep.height())
                                 .arg(editor_->document().render.width)
                                 .arg(editor_->document().render.height),
                             5000);
    return true;
}

void MainWindow::exportImageDialog() {
    // The viewport's frame has the viewport's size: the dialog says so before anything is written.
    const auto frame = viewport_->frame();
    const QString title = frame && !frame->empty()
                              ? tr("Export Current Frame (%1x%2, the viewport's size)")
                                    .arg(frame->width)
                                    .arg(frame->height)
                              : tr("Export Current Frame");
    const QString path = QFileDialog::getSaveFileName(
        this, title, dialogFolder(FileKind::Image, editor_->filePath()), kImageFilter);
    rememberDialogFolder(FileKind::Image, path);
    if (!path.isEmpty()) exportFrame(path);
}

void MainWindow::renderImageDialog() {
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Render Image"));
    auto* form = new QFormLayout(&dialog);
    auto* width = new QSpinBox(&dialog);
    auto* height = new QSpinBox(&dialog);
    // The format's range, from its descriptors (scene/parameters.cpp).
    for (auto [spin, key] : {std::pair{width, "width"}, std::pair{height, "height"}}) {
        const ParamDescriptor* d = findParameter(ParamKind::Render, key);
        spin->setRange(int(d->range.min), int(d->range.max));
    }
    width->setValue(editor_->document().render.width);
    height->setValue(editor_->document().render.height);
    form->addRow(tr("Width"), width);
    form->addRow(tr("Height"), height);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted) return;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Render Image To"), dialogFolder(FileKind::Image, editor_->filePath()),
        kImageFilter);
    if (path.isEmpty()) return;
    rememberDialogFolder(FileKind::Image, path);
    renderImage(path, width->value(), height->value());
}

ClusterSubmitDialog* MainWindow::submitToClusterDialog() {
    if (editor_->filePath().isEmpty() || !editor_->undoStack()->isClean()) {
        if (!confirm(this, tr("Submit to Cluster"),
                     tr("The cluster's nodes render the scene file, not the open document. "
                        "Save the scene first?")) ||
            !save())
            return nullptr;
    }
    const SceneDocument& doc = editor_->document();
    auto* dialog =
        new ClusterSubmitDialog(editor_->filePath(), doc.render.width, doc.render.height, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    return dialog;
}

bool MainWindow::renderImage(const QString& path, int width, int height) {
    SceneDocument doc = editor_->document();
    doc.render.width = width;
    doc.render.height = height;
    if (const std::string over = budgetExceeded(estimateCost(doc)); !over.empty()) {
        const QString text =
            tr("Over the cost budget: %1.\n\nIt may take hours or exhaust memory. Render anyway?")
                .arg(QString::fromStdString(over));
        if (!confirm(this, tr("Render over the cost budget"), text)) {
            statusBar()->showMessage(tr("Render not started: over the cost budget"), 5000);
            return false;
        }
    }
    // Its own thread count (Preferences): on few cores the viewport keeps what is left.
    RenderQueue* queue = renders_->queue();
    queue->enqueue(doc, path, prefs_.renderThreads, prefs_.engine);
    if (queue->queued() > 0)
        statusBar()->showMessage(
            tr("Render of %1 queued behind %2 more render(s)").arg(path).arg(queue->queued()),
            3000);
    return true;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    for (const QUrl& url : event->mimeData()->urls()) {
        const QString path = url.toLocalFile();
        if (path.isEmpty()) continue;
        if (isSceneFile(path)) {
            if (maybeSave()) openFile(path);
            break;
        }
        const QPoint at = viewport_->mapFrom(this, event->position().toPoint());
        if (isTextureFileName(path.toStdString())) {
            // An image: the texture of the object under the cursor, picked as a click would.
            const auto pixel =
                viewport_->rect().contains(at) ? viewport_->pixelAt(at) : std::nullopt;
            const ObjectId id =
                pixel ? viewport_->frame()->idAt(pixel->x(), pixel->y()) : kNoObject;
            statusBar()->showMessage(dropTexture(*editor_, id, QFileInfo(path).absoluteFilePath()),
                                     8000);
            break;
        }
        // Dropped on the viewport: the mesh lands on the surface under the cursor.
        importMesh(path, viewport_->rect().contains(at) ? std::optional<QPoint>(at) : std::nullopt);
    }
    event->acceptProposedAction();
}

Placement MainWindow::placementAt(std::optional<QPoint> at) const {
    // New things appear where the user looks through the view camera (not the scene
    // camera): on the surface under the viewport's centre or the cursor.
    const Camera& view = viewport_->viewCamera();
    const ViewProjection projection = viewport_->projection();
    const Ray ray = projection.valid()
                        ? projection.rayThrough(QPointF(at.value_or(viewport_->rect().center())))
                        : Ray::make(view.position, view.target - view.position);
    // The snapshot must hold the latest edits: its surfaces are the ones hit.
    session_->flushUpdate();
    const auto snapshot = session_->session().snapshot();
    return placeAlong(snapshot.get(), ray, fallbackDistance(view));
}

void MainWindow::placeNew(SceneDocument& doc, ObjectId id, const Placement& at) const {
    restOn(doc, id, at);
    if (!snapToFloorAct_->isChecked() || !doc.findObject(id)) return;
    const Vec3 up = doc.camera.up;
    const float len = glm::length(up);
    const auto snapshot = session_->session().snapshot();
    snapToFloor(doc, id, snapshot.get(), len > 1e-6f ? up / len : Vec3(0.0f, 1.0f, 0.0f));
}

Vec3 MainWindow::placeNewInView(SceneDocument& doc, ObjectId id) const {
    const float len = glm::length(doc.camera.up);
    const Vec3 up = len > 1e-6f ? doc.camera.up / len : Vec3(0.0f, 1.0f, 0.0f);
    session_->flushUpdate();  // The snapshot's surfaces must be the document's.
    const auto snapshot = session_->session().snapshot();
    const QSize size = viewport_->size();
    const float aspect = size.height() > 0 ? float(size.width()) / float(size.height()) : 1.0f;
    return placeInView(doc, id, snapshot.get(), viewport_->viewCamera(), up, aspect);
}

void MainWindow::addShapeAction(ShapeKind kind) {
    SceneDocument doc = editor_->document();
    const ObjectId id = addShape(doc, kind, Vec3(0.0f));
    placeNewInView(doc, id);
    const QString text = tr("Add %1").arg(QString::fromStdString(doc.findObject(id)->name));
    editor_->edit(text, std::move(doc));
    editor_->setSelection(id);
}

void MainWindow::addLightAction(LightType type) {
    SceneDocument doc = editor_->document();
    const ObjectId id = addLight(doc, type, Vec3(0.0f));
    placeNewInView(doc, id);
    const QString text = tr("Add %1").arg(QString::fromStdString(doc.findLight(id)->name));
    editor_->edit(text, std::move(doc));
    editor_->setSelection(id);
}

void MainWindow::deleteSelection() {
    // Every selected entity, in one undo step.
    SceneDocument doc = editor_->document();
    int removed = 0;
    for (ObjectId id : editor_->selectedIds()) removed += remove(doc, id);
    if (removed == 0) return;
    editor_->edit(removed == 1 ? tr("Delete") : tr("Delete %1 items").arg(removed), std::move(doc));
    editor_->setSelection(kNoObject);
}

void MainWindow::duplicateSelection() {
    // The copies, in one undo step, become the selection.
    SceneDocument doc = editor_->document();
    std::vector<ObjectId> copies;
    for (ObjectId id : editor_->selectedIds())
        if (const ObjectId copy = duplicate(doc, id); copy != kNoObject) copies.push_back(copy);
    if (copies.empty()) return;
    editor_->edit(
        copies.size() == 1 ? tr("Duplicate") : tr("Duplicate %1 items").arg(copies.size()),
        std::move(doc));
    editor_->setSelection(copies);
}

}  // namespace rs::ui
