// raystudio: the designer. Opens the scene given on the command line, or the bundled
// reference room found next to the build tree or the installed data.
#include "default_scene.h"
#include "drag_measurement.h"
#include "main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>

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
    const QString scene = args.isEmpty()
                              ? rs::ui::defaultScenePath(QCoreApplication::applicationDirPath())
                              : args.first();
    if (!scene.isEmpty()) window.openFile(scene);
    return app.exec();
}
