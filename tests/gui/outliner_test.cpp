// The outliner at scale: an edit signals only the rows it changed, structure changes insert
// or remove rows instead of resetting the model, and the view lays rows out uniformly (the
// designer spent a quarter of a move of one of 10,000 spheres measuring every row).
#include <QSignalSpy>
#include <QtTest>

#include "document/scene_editor.h"
#include "panels/outliner_model.h"
#include "panels/outliner_view.h"
#include "test_scenes.h"

using namespace rs;
using namespace rs::ui;

namespace {

using rs::test::manySpheres;

/// How many rows the dataChanged signals of `spy` covered.
int rowsSignalled(const QSignalSpy& spy) {
    int rows = 0;
    for (const auto& args : spy)
        rows += args[1].toModelIndex().row() - args[0].toModelIndex().row() + 1;
    return rows;
}

}  // namespace

class OutlinerTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init() {
        editor_ = std::make_unique<SceneEditor>();
        editor_->resetDocument(manySpheres(10000), QString());
        model_ = std::make_unique<OutlinerModel>(editor_.get());
    }
    void cleanup() {
        model_.reset();
        editor_.reset();
    }

    void movingAnObject_SignalsNoRow() {
        QSignalSpy changed(model_.get(), &QAbstractItemModel::dataChanged);
        QSignalSpy reset(model_.get(), &QAbstractItemModel::modelReset);
        SceneDocument doc = editor_->document();
        doc.objects[5000].transform.translate = Vec3(0.0f, 1.0f, 0.0f);
        editor_->edit(QStringLiteral("Move"), std::move(doc));
        QCOMPARE(reset.count(), 0);
        QCOMPARE(rowsSignalled(changed), 0);  // name and visibility are what rows show
    }

    void renamingOrHidingOne_SignalsThatRowAlone() {
        QSignalSpy changed(model_.get(), &QAbstractItemModel::dataChanged);
        SceneDocument doc = editor_->document();
        doc.objects[1234].name = "renamed";
        doc.objects[1234].visible = false;
        const ObjectId id = doc.objects[1234].id;
        editor_->edit(QStringLiteral("Rename"), std::move(doc));
        QCOMPARE(changed.count(), 1);
        QCOMPARE(rowsSignalled(changed), 1);
        const QModelIndex row = changed[0][0].toModelIndex();
        QCOMPARE(model_->idOf(row), id);
        QCOMPARE(model_->data(row, Qt::DisplayRole).toString(), QStringLiteral("renamed"));
        QCOMPARE(model_->data(row, Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    }

    void addingAndDeleting_InsertAndRemoveRows_WithoutAReset() {
        QSignalSpy reset(model_.get(), &QAbstractItemModel::modelReset);
        QSignalSpy inserted(model_.get(), &QAbstractItemModel::rowsInserted);
        QSignalSpy removed(model_.get(), &QAbstractItemModel::rowsRemoved);
        const QModelIndex objects = model_->index(2, 0);
        QCOMPARE(model_->rowCount(objects), 10000);

        SceneDocument doc = editor_->document();
        Object extra;
        extra.name = "extra";
        const ObjectId added = doc.addObject(extra);
        editor_->edit(QStringLiteral("Add"), std::move(doc));
        QCOMPARE(inserted.count(), 1);
        QCOMPARE(model_->rowCount(objects), 10001);
        QCOMPARE(model_->idOf(model_->index(10000, 0, objects)), added);

        doc = editor_->document();
        const ObjectId gone = doc.objects[10].id;
        doc.objects.erase(doc.objects.begin() + 10);
        editor_->edit(QStringLiteral("Delete"), std::move(doc));
        QCOMPARE(removed.count(), 1);
        QCOMPARE(model_->rowCount(objects), 10000);
        QVERIFY(!model_->indexOf(gone).isValid());
        QCOMPARE(reset.count(), 0);

        // Undo puts the deleted object back where it was: one inserted row.
        editor_->undoStack()->undo();
        QCOMPARE(inserted.count(), 2);
        QCOMPARE(model_->idOf(model_->index(10, 0, objects)), gone);
        QCOMPARE(reset.count(), 0);
    }

    void everyIdIsFoundAtItsRow() {
        const QModelIndex objects = model_->index(2, 0);
        for (int r : {0, 1, 4999, 9998, 9999}) {
            const QModelIndex row = model_->index(r, 0, objects);
            QCOMPARE(model_->indexOf(model_->idOf(row)), row);
        }
        QCOMPARE(model_->indexOf(editor_->document().lights[0].id),
                 model_->index(0, 0, model_->index(1, 0)));
    }

    void theView_LaysOutRowsUniformly() {
        OutlinerView view(editor_.get(), {});
        QVERIFY(view.uniformRowHeights());
    }

    void theNameFilter_ShowsTheMatchingRows_AndKeepsTheSelection() {
        OutlinerView view(editor_.get(), {});
        const ObjectId ball5 = editor_->document().objects[5].id;
        const ObjectId ball1234 = editor_->document().objects[1234].id;
        editor_->setSelection(ball5);
        QCOMPARE(view.idOf(view.currentIndex()), ball5);

        // "sphere 12", "sphere 120".."sphere 129", "sphere 1200".."sphere 1299": 111 rows, any
        // case.
        view.setNameFilter(QStringLiteral("SPHERE 12"));
        const QModelIndex objects = view.model()->index(view.model()->rowCount() - 1, 0);
        QCOMPARE(view.model()->rowCount(objects), 111);
        for (int r = 0; r < 111; ++r) {
            const ObjectId id = view.idOf(view.model()->index(r, 0, objects));
            QVERIFY(editor_->document().findObject(id)->name.starts_with("sphere 12"));
        }
        QVERIFY(!view.indexOf(ball5).isValid());  // Filtered out...
        QCOMPARE(editor_->selection(), ball5);    // ...and still the selected object.

        // Picking a shown row selects it; a rename the filter no longer matches hides it.
        view.setCurrentIndex(view.indexOf(ball1234));
        QCOMPARE(editor_->selection(), ball1234);
        SceneDocument doc = editor_->document();
        doc.findObject(ball1234)->name = "renamed";
        editor_->edit(QStringLiteral("Rename"), std::move(doc));
        QCOMPARE(view.model()->rowCount(objects), 110);

        view.setNameFilter({});
        QCOMPARE(view.model()->rowCount(view.model()->index(2, 0)), 10000);
        QCOMPARE(view.idOf(view.currentIndex()), editor_->selection());
    }

private:
    std::unique_ptr<SceneEditor> editor_;
    std::unique_ptr<OutlinerModel> model_;
};

QTEST_MAIN(OutlinerTest)
#include "outliner_test.moc"
