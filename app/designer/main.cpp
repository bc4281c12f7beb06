// raystudio: the designer. Opens the scene given on the command line, or the bundled
// reference room found next to the build tree or the installed data.
#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QIcon>
#include <QSurfaceFormat>
#include <cstdio>
#include <cstring>

#include "document/default_scene.h"
#include "document/scene_editor.h"
#include "drag_measurement.h"
#include "raystudio_version.h"
#include "shell/main_window.h"

namespace {
int usageError(const char* message) {
    std::fprintf(stderr, "raystudio: %s\n", message);
    return 2;
}
/// The designer's options (--help lists them; a headless machine can ask for it too).
struct Options {
    QCommandLineOption autosave{
        QStringLiteral("autosave-seconds"),
        QStringLiteral("Autosave interval for this run, overriding Preferences (0: off)."),
        QStringLiteral("seconds")};
    QCommandLineOption recover{
        QStringLiteral("recover"),
        QStringLiteral("What to do with a crashed session's autosave: ask (default), yes or no."),
        QStringLiteral("ask|yes|no"), QStringLiteral("ask")};
    // For the packaging test and bug reports: opens the scene as a start would, prints the
    // path it opened on stdout and exits (1 when nothing could be opened).
    QCommandLineOption opened{
        QStringLiteral("print-opened-scene"),
        QStringLiteral("Open the scene (or the default one), print its path and exit.")};
    // For scripted sessions (tests/bench/window-frames.sh): start with an object selected,
    // as a click in the outliner would.
    QCommandLineOption select{QStringLiteral("select"),
                              QStringLiteral("Select the object or light named NAME on opening."),
                              QStringLiteral("NAME")};
};

void describe(QCommandLineParser& parser, const Options& options) {
    parser.setApplicationDescription(
        QStringLiteral("Interactive Whitted ray-traced scene designer"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("scene"),
        QStringLiteral("Scene file to open (default: the bundled reference room)."));
    rs::ui::addMeasurementOptions(parser);
    // Both exist for scripted runs (the recovery tests, kiosks): a short interval and no dialog.
    parser.addOption(options.autosave);
    parser.addOption(options.recover);
    parser.addOption(options.opened);
    parser.addOption(options.select);
}
/// --version and --help, answered before QApplication, which needs a display: they work on a
/// headless machine too. -1 when neither was asked for.
int answerWithoutDisplay(int argc, char* argv[]) {
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--version") == 0) {
            std::puts("raystudio " RAYSTUDIO_VERSION_STRING);
            return 0;
        }
        if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0 ||
            std::strcmp(argv[i], "--help-all") == 0) {
            QCoreApplication core(argc, argv);  // no display needed to print the help
            QCoreApplication::setApplicationName(QStringLiteral("raystudio"));
            QCoreApplication::setApplicationVersion(QStringLiteral(RAYSTUDIO_VERSION_STRING));
            QCommandLineParser parser;
            const Options options;
            describe(parser, options);
            parser.process(core);  // prints the help and exits
            return 0;
        }
    }
    return -1;
}

/// The window icon, from the PNG renders of resources/icons/raystudio.svg.
void setWindowIcon() {
    QIcon icon;
    for (const char* size : {"16x16", "32x32", "48x48", "256x256"})
        icon.addFile(QStringLiteral(":/icons/%1/raystudio.png").arg(QLatin1String(size)));
    QApplication::setWindowIcon(icon);
}

/// --select NAME: selects the object or light named NAME, as a click in the outliner would.
void selectNamed(rs::ui::MainWindow& window, const QString& scene, const std::string& name) {
    const rs::SceneDocument& doc = window.editor()->document();
    rs::ObjectId id = rs::kNoObject;
    for (const rs::Object& o : doc.objects)
        if (o.name == name) id = o.id;
    for (const rs::Light& l : doc.lights)
        if (id == rs::kNoObject && l.name == name) id = l.id;
    if (id == rs::kNoObject)
        std::fprintf(stderr, "raystudio: --select: %s has no object or light named '%s'\n",
                     qPrintable(scene), name.c_str());
    else
        window.editor()->setSelection(id);
}

}  // namespace

int main(int argc, char* argv[]) {
    if (const int rc = answerWithoutDisplay(argc, argv); rc >= 0) return rc;
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("RayStudio"));
    QCoreApplication::setApplicationName(QStringLiteral("RayStudio"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RAYSTUDIO_VERSION_STRING));
    setWindowIcon();
    QCommandLineParser parser;
    const Options options;
    describe(parser, options);
    parser.process(app);
    if (const int rc = rs::ui::runRequestedMeasurement(parser); rc >= 0) return rc;

    using Answer = rs::ui::MainWindow::RecoveryAnswer;
    const QString recover = parser.value(options.recover);
    if (recover != QLatin1String("ask") && recover != QLatin1String("yes") &&
        recover != QLatin1String("no"))
        return usageError("--recover must be ask, yes or no");
    const Answer answer = recover == QLatin1String("yes")  ? Answer::Recover
                          : recover == QLatin1String("no") ? Answer::Discard
                                                           : Answer::Ask;

    rs::ui::MainWindow window;
    if (parser.isSet(options.autosave)) {
        bool ok = false;
        const double seconds = parser.value(options.autosave).toDouble(&ok);
        if (!ok || seconds < 0.0 || seconds > 86400.0)
            return usageError("--autosave-seconds must be in [0, 86400]");
        window.setAutosaveIntervalMs(int(seconds * 1000.0 + 0.5));
    }
    window.show();
    const QStringList args = parser.positionalArguments();
    const QString scene = args.isEmpty()
                              ? rs::ui::defaultScenePath(QCoreApplication::applicationDirPath())
                              : args.first();
    const bool opened = !scene.isEmpty() && window.openFile(scene);
    if (parser.isSet(options.opened)) {
        if (!opened) return 1;
        std::printf("%s\n", qPrintable(QFileInfo(scene).canonicalFilePath()));
        return 0;
    }
    if (parser.isSet(options.select) && opened)
        selectNamed(window, scene, parser.value(options.select).toStdString());
    window.offerRecovery(answer);
    return app.exec();
}
