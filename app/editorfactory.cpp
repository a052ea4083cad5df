// SPDX-License-Identifier: MIT
#include "editorfactory.h"

#include "componenteditor.h"
#include "rtcdocument.h"
#include "rtsdocument.h"
#include "rtseditor.h"

namespace Studio {

QWidget *createEditor(Document *document, QWidget *parent)
{
    if (auto *rtc = qobject_cast<RtcDocument *>(document))
        return new Builder::ComponentEditor(rtc->model(), rtc->undoStack(), nullptr, parent);
    if (auto *rts = qobject_cast<RtsDocument *>(document))
        return new RtsEditor(rts, parent);
    return nullptr;
}

} // namespace Studio
