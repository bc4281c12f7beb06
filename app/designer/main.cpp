// raystudio: the designer. Opens the scene given on the command line, or the bundled
// reference room found next to the build tree or the installed data.
#include "drag_measurement.h"
#include "main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QSurfaceFormat>

namespace {

/// scenes/reference-room.scene.json relative to the executable (build tree: two levels up;
/// installed: ../share/raystudio), or the working folder.
QString defaultScene() {
    const QString name = QStringLiteral("scenes/reference-room.scene.json");
    const QDir exe(QCoreApplication::applicationDirPath());
    const QStringList candidates = {
        exe.filePath(QStringLiteral("../../") + name),
        exe.filePath(QStringLiteral("../share/raystudio/") + name),
        exe.filePath(QStringLiteral("../") + name),
        exe.filePath(name),
        QDir::current().filePath(name),
    };
    for (const QString& c : candidates)
        if (QFileInfo::exists(c)) return QFileInfo(c).canonicalFilePath();
    return {};
}

}  // namespace

int main(int argc, char* argv[]) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("RayStudio"));
    QCoreApplication::setApplicationName(QStringLiteral("RayStudio"));
    QCoreApplication::setApplicationVersion(QStringLiteral("0.1.0"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Interactive Whitted ray-traced scene designer"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("scene"), QStringLiteral("Scene file to open."));
    rs::ui::addMeasurementOptions(parser);
    parser.process(app);
    if (const int rc = rs::ui::runRequestedMeasurement(parser); rc >= 0) return rc;

    rs::ui::MainWindow window;
    window.show();
    const QStringList args = parser.positionalArguments();
    const QString scene = args.isEmpty() ? defaultScene() : args.first();
    if (!scene.isEmpty()) window.openFile(scene);
    return app.exec();
}
