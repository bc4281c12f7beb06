// Item model of the outliner: the camera, the lights and the objects of the document.
#pragma once

#include <QAbstractItemModel>

#include "scene/document.h"

namespace rs::ui {

class SceneEditor;

/// Two-level tree: "Camera", "Lights" (children), "Objects" (children). Objects have a
/// visibility checkbox; lights and objects can be renamed in place.
class OutlinerModel : public QAbstractItemModel {
    Q_OBJECT
public:
    explicit OutlinerModel(SceneEditor* editor, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    /// The id an index stands for (SceneEditor::kCameraSelection for the camera row,
    /// kNoObject for group rows).
    ObjectId idOf(const QModelIndex& index) const;
    /// The index of a light, object or the camera; invalid when absent.
    QModelIndex indexOf(ObjectId id) const;

private:
    /// What a row shows, kept so that an edit updates only the rows whose text or check
    /// changed (a move changes none: 10,000 rows are not re-measured per mouse move).
    struct Row {
        ObjectId id = kNoObject;
        std::string name;
        bool visible = true;
        bool operator==(const Row&) const = default;
    };
    void onDocumentChanged();
    /// Brings group `group`'s rows to `rows`: inserts or removes a contiguous run when that is
    /// the whole difference of ids, then signals the rows whose text or check changed.
    /// Returns false when the ids changed otherwise (the caller resets the model).
    bool update(int group, std::vector<Row>& cached, const std::vector<Row>& rows);
    const std::vector<Row>& rowsOf(int group) const;
    std::vector<Row> lightRows_, objectRows_;
    SceneEditor* editor_;
};

}  // namespace rs::ui
