// SPDX-License-Identifier: MIT
#include "editorfactory.h"

#include "componenteditor.h"
#include "generatedialogprompts.h"
#include "onlinediagram.h"
#include "onlinedocument.h"
#include "rtcdocument.h"
#include "rtsdocument.h"
#include "rtseditor.h"

#include <QPointer>

namespace Studio {

QWidget *createEditor(Document *document, QWidget *parent)
{
    if (auto *rtc = qobject_cast<RtcDocument *>(document)) {
        auto *editor
            = new Builder::ComponentEditor(rtc->model(), rtc->undoStack(), nullptr, parent);
        const QPointer<RtcDocument> source(rtc);
        Builder::installGenerateController(
            editor, [source] { return source ? source->filePath() : QString(); });
        return editor;
    }
    if (auto *online = qobject_cast<OnlineDocument *>(document)) {
        auto *diagram = new SystemEditor::OnlineDiagram(online->session(), parent);
        online->setDiagram(diagram);
        return diagram;
    }
    if (auto *rts = qobject_cast<RtsDocument *>(document))
        return new RtsEditor(rts, parent);
    return nullptr;
}

} // namespace Studio
