// SPDX-License-Identifier: MIT
#include "clienttls.h"
#include "diagramexport.h"
#include "interruptsignals.h"
#include "mainwindow.h"
#include "onlinedocks.h"
#include "rtsdocument.h"
#include "rtstudioresources.h"
#include "uilanguage.h"

#include <QApplication>
#include <QStatusBar>
#include <QByteArray>
#include <QCommandLineParser>
#include <QIcon>

#include <cstdio>

namespace {

/// True when the command line asks only for what needs no display: a diagram export, the usage or
/// the version (over ssh, in a script).
bool needsNoDisplay(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray argument(argv[i]);
        if (argument.startsWith("--export-diagram") || argument.startsWith("--help")
            || argument == "--version" || argument == "-h" || argument == "-?" || argument == "-v")
            return true;
    }
    return false;
}

/// `--export-diagram SYSTEM --output OUT`: 0 on success, 1 with a message on failure.
int exportDiagram(const QCommandLineParser &parser, const QCommandLineOption &output)
{
    const QString system = parser.value(QStringLiteral("export-diagram"));
    if (!parser.isSet(output)) {
        std::fprintf(stderr, "%s\n",
                     qPrintable(QApplication::translate(
                         "main", "--export-diagram needs --output OUT.png or OUT.svg")));
        return 1;
    }
    QString error;
    if (!SystemEditor::DiagramExport::exportSystemFile(system, parser.value(output), &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    return 0;
}

/**
 * SIGTERM, SIGINT and SIGHUP close the window as its close button does: unsaved work is asked
 * about, and the local runtime this window started stops unless the user keeps it. A second
 * signal while that question waits (or after the user kept the window) ends the program at once,
 * still stopping that runtime; the unsaved work is lost then, as the sender insisted.
 */
void closeOnSignals(Codegen::InterruptSignals *interrupts, Studio::MainWindow *window)
{
    QObject::connect(interrupts, &Codegen::InterruptSignals::received, window,
                     [window, asked = false](int signal) mutable {
                         if (!asked) {
                             asked = true;
                             window->close();
                             return;
                         }
                         window->onlineDocks()->quitting();
                         Codegen::InterruptSignals::endAsSignalled(signal);
                     });
}

} // namespace

int main(int argc, char *argv[])
{
    if (needsNoDisplay(argc, argv) && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RtStudio"));
    QApplication::setApplicationName(QStringLiteral("rtstudio"));
    QApplication::setApplicationDisplayName(QStringLiteral("RT Studio"));
    QApplication::setApplicationVersion(QStringLiteral(RTSTUDIO_VERSION));
    QApplication::setWindowIcon(QIcon(Resources::applicationIconPath()));
    QString languageError;
    if (!Studio::UiLanguage::install(
            &app, Studio::UiLanguage::resolve(Studio::UiLanguage::chosen()), &languageError))
        std::fprintf(stderr, "%s\n", qPrintable(languageError));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "IDE for OpenRTM-aist RT-Components and RT Systems."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption exportOption(
        QStringLiteral("export-diagram"),
        QApplication::translate("main", "Render the diagram of a system file without a window."),
        QStringLiteral("SYSTEM"));
    const QCommandLineOption outputOption(
        QStringLiteral("output"),
        QApplication::translate("main", "Where --export-diagram writes (.png or .svg)."),
        QStringLiteral("OUT"));
    const QCommandLineOption runOption(
        QStringLiteral("run-locally"),
        QApplication::translate("main", "Open a system, run it on the local runtime (started when needed) "
                                        "and show it online with its first connection in the Port Monitor."),
        QStringLiteral("SYSTEM"));
    parser.addOption(exportOption);
    parser.addOption(outputOption);
    parser.addOption(runOption);
    parser.addPositionalArgument(
        QStringLiteral("files"),
        QApplication::translate("main", "RTC or RTS profiles to open (XML or YAML)."),
        QStringLiteral("[FILE…]"));
    parser.process(app);
    if (parser.isSet(exportOption))
        return exportDiagram(parser, outputOption);

    // Before any remote call: TLS as the environment or a local runtime started with --tls says.
    QString tlsError;
    const bool tlsUsable = Deploy::configureClientTls(&tlsError);
    Studio::MainWindow window;
    if (!tlsUsable)
        window.statusBar()->showMessage(QApplication::translate("main", "TLS: %1").arg(tlsError));
    if (!tlsUsable)
        std::fprintf(stderr, "rtstudio: TLS: %s\n", qPrintable(tlsError));
    Codegen::InterruptSignals interrupts;
    closeOnSignals(&interrupts, &window);
    window.show();
    if (parser.isSet(runOption)) {
        const QString system = parser.value(runOption);
        if (!window.openFiles({system}))
            return 1;
        if (auto *rts = qobject_cast<Studio::RtsDocument *>(window.activeDocument()))
            window.onlineDocks()->runLocally(rts->profile());
    }
    if (!parser.positionalArguments().isEmpty())
        window.openFiles(parser.positionalArguments());
    return app.exec();
}
