// DockedPanels: the outliner, properties, materials and world panels in their docks.
#include "shell/docked_panels.h"

#include <QDockWidget>
#include <QLineEdit>
#include <QMainWindow>
#include <QVBoxLayout>

#include "panels/material_list.h"
#include "panels/outliner_view.h"
#include "panels/property_panel.h"
#include "panels/world_panel.h"

namespace rs::ui {

namespace {
/// A dock titled `title` holding `widget`, added to `window` in `area`.
QDockWidget* dock(QMainWindow* window, const QString& title, const char* name, QWidget* widget,
                  Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, window);
    d->setObjectName(QString::fromLatin1(name));
    d->setWidget(widget);
    window->addDockWidget(area, d);
    return d;
}
}  // namespace

DockedPanels::DockedPanels(SceneEditor* editor, const QList<QAction*>& outlinerActions,
                           QMainWindow* window)
    : QObject(window) {
    dockOutliner(editor, outlinerActions, window);
    properties_ = new PropertyPanel(editor, window);
    dock(window, tr("Properties"), "propertiesDock", properties_, Qt::RightDockWidgetArea);
    materials_ = new MaterialList(editor, window);
    QDockWidget* materialsDock =
        dock(window, tr("Materials"), "materialsDock", materials_, Qt::RightDockWidgetArea);
    world_ = new WorldPanel(editor, window);
    QDockWidget* worldDock =
        dock(window, tr("World"), "worldDock", world_, Qt::RightDockWidgetArea);
    window->tabifyDockWidget(materialsDock, worldDock);  // Beside the materials: the looks.
    materialsDock->raise();
}

void DockedPanels::dockOutliner(SceneEditor* editor, const QList<QAction*>& actions,
                                QMainWindow* window) {
    auto* outlinerPane = new QWidget(window);
    auto* outlinerLayout = new QVBoxLayout(outlinerPane);
    outlinerLayout->setContentsMargins(0, 0, 0, 0);
    outlinerLayout->setSpacing(2);
    auto* nameFilter = new QLineEdit(outlinerPane);
    nameFilter->setObjectName(QStringLiteral("outlinerFilter"));
    nameFilter->setPlaceholderText(tr("Filter by name"));
    nameFilter->setClearButtonEnabled(true);
    outliner_ = new OutlinerView(editor, actions, outlinerPane);
    connect(nameFilter, &QLineEdit::textChanged, outliner_, &OutlinerView::setNameFilter);
    outlinerLayout->addWidget(nameFilter);
    outlinerLayout->addWidget(outliner_);
    dock(window, tr("Outliner"), "outlinerDock", outlinerPane, Qt::LeftDockWidgetArea);
}

}  // namespace rs::ui
