// SPDX-License-Identifier: MIT
#include "documentloader.h"

#include "profileio.h"
#include "rtcdocument.h"
#include "rtsdocument.h"

#include <QCoreApplication>

namespace Studio {

std::unique_ptr<Document> loadDocument(const QString &path, Profile::Diagnostics *diagnostics)
{
    std::optional<Profile::LoadedProfile> loaded = Profile::loadProfileFile(path, diagnostics);
    if (!loaded)
        return nullptr;
    return documentFromProfile(std::move(*loaded), path, diagnostics);
}

std::unique_ptr<Document> documentFromProfile(Profile::LoadedProfile loaded, const QString &path,
                                              Profile::Diagnostics *diagnostics)
{
    std::unique_ptr<Document> document;
    if (loaded.kind == Profile::ProfileKind::Rtc && loaded.rtc)
        document = std::make_unique<RtcDocument>(std::move(*loaded.rtc));
    else if (loaded.kind == Profile::ProfileKind::Rts && loaded.rts)
        document = std::make_unique<RtsDocument>(std::move(*loaded.rts));
    if (!document) {
        // The facade promises a model for the kind it reports; guard against a broken promise
        // rather than crash.
        if (diagnostics) {
            diagnostics->append(Profile::Diagnostic::error(
                path, 0, 0,
                QCoreApplication::translate("Studio::loadDocument", "not an RTC or RTS profile")));
        }
        return nullptr;
    }
    document->attachToFile(path, loaded.format, loaded.diagnostics);
    return document;
}

} // namespace Studio
