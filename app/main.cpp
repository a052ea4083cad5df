// SPDX-License-Identifier: MIT
#include "mainwindow.h"
#include "rtstudioresources.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RtStudio"));
    QApplication::setApplicationName(QStringLiteral("rtstudio"));
    QApplication::setApplicationDisplayName(QStringLiteral("RT Studio"));
    QApplication::setApplicationVersion(QStringLiteral(RTSTUDIO_VERSION));
    QApplication::setWindowIcon(QIcon(Resources::applicationIconPath()));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "IDE for OpenRTM-aist RT-Components and RT Systems."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("files"),
        QApplication::translate("main", "RTC or RTS profiles to open (XML or YAML)."),
        QStringLiteral("[FILE…]"));
    parser.process(app);

    Studio::MainWindow window;
    window.show();
    if (!parser.positionalArguments().isEmpty())
        window.openFiles(parser.positionalArguments());
    return app.exec();
}
