// SPDX-License-Identifier: MIT
#include "onlinedocument.h"

#include "onlinediagram.h"
#include "profileio.h"
#include "systemmodel.h"

namespace Studio {

OnlineDocument::OnlineDocument(SystemEditor::OnlineSession *session, QObject *parent)
    : Document(parent)
    , m_session(session)
{ }

SystemEditor::OnlineDiagram *OnlineDocument::diagram() const
{
    return static_cast<SystemEditor::OnlineDiagram *>(m_diagram.data());
}

void OnlineDocument::setDiagram(SystemEditor::OnlineDiagram *diagram)
{
    m_diagram = diagram;
    connect(diagram, &SystemEditor::OnlineDiagram::liveSystemSaved, this,
            &OnlineDocument::liveSaved);
}

QByteArray OnlineDocument::serialize(Profile::FileFormat format) const
{
    if (!m_diagram)
        return {};
    return Profile::serializeRtsProfile(diagram()->model()->profile(), format);
}

bool OnlineDocument::saveLive(const QString &path)
{
    if (!m_diagram)
        return false;
    diagram()->saveLiveSystem(path);
    return true;
}

} // namespace Studio
