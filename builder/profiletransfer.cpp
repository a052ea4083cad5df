// SPDX-License-Identifier: MIT
#include "profiletransfer.h"

#include "componentcommands.h"
#include "componentmodel.h"
#include "profileio.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace Builder::ProfileTransfer {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Builder::ProfileTransfer)
};

} // namespace

QUndoCommand *importCommand(ComponentModel *model, const QString &path,
                            Profile::Diagnostics *diagnostics)
{
    const std::optional<Profile::LoadedProfile> loaded
        = Profile::loadProfileFile(path, diagnostics);
    if (!loaded)
        return nullptr;
    if (loaded->kind != Profile::ProfileKind::Rtc || !loaded->rtc) {
        // Importing a system would replace the component with nothing it could describe.
        diagnostics->append(Profile::Diagnostic::error(
            path, 0, 0,
            Text::tr("This file holds a system (RTS Profile), not a component; open it in the System "
               "Editor instead.")));
        return nullptr;
    }
    if (*loaded->rtc == model->profile())
        return nullptr;
    auto *command = new ReplaceProfileCommand(model, *loaded->rtc);
    command->setText(Text::tr("Import %1").arg(QFileInfo(path).fileName()));
    return command;
}

bool exportProfile(const Profile::RtcProfile &profile, const QString &path,
                   Profile::Diagnostics *diagnostics)
{
    return Profile::saveRtcProfileFile(profile, path, diagnostics);
}

QString fileFilter()
{
    return Text::tr("RTC Profile (*.xml *.yaml *.yml);;All files (*)");
}

} // namespace Builder::ProfileTransfer
