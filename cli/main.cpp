// SPDX-License-Identifier: MIT
#include "commandline.h"

#include <QCoreApplication>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rtctl"));
    QCoreApplication::setOrganizationName(QStringLiteral("RTStudio"));

    QTextStream out(stdout);
    QTextStream err(stderr);
    const int code = Cli::createCommandLine()->run(app.arguments().mid(1), Cli::Streams{out, err});
    out.flush();
    err.flush();
    return code;
}
