// SPDX-License-Identifier: MIT
// The view's in-place editing: renaming an instance, and the choices of the connector dialog.
#include "systemview.h"

#include "componentitem.h"
#include "connectionrules.h"
#include "systemscene.h"

#include "profileio.h"
#include "rtcrepository.h"

#include <QDragEnterEvent>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMimeData>
#include <QUrl>

namespace SystemEditor {

namespace {

/// A line edit that reports Escape, which QLineEdit itself ignores.
class RenameEdit : public QLineEdit
{
public:
    using QLineEdit::QLineEdit;
    std::function<void()> onEscape;

protected:
    void keyPressEvent(QKeyEvent *event) override
    {
        if (event->key() == Qt::Key_Escape && onEscape) {
            onEscape();
            return;
        }
        QLineEdit::keyPressEvent(event);
    }
};

/// The comma-separated values of an RTC profile's port attribute, e.g. `push,pull`.
QStringList listOf(const std::optional<QString> &text)
{
    QStringList items;
    for (const QString &item : text.value_or(QString()).split(QLatin1Char(','), Qt::SkipEmptyParts))
        items << item.trimmed();
    return items;
}

const Profile::RtcDataPort *rtcPort(const SystemModel &model, const ConnectorEnd &end)
{
    const Profile::RtcProfile *rtc = model.rtcProfile(end.instanceName);
    const std::optional<PortInfo> port = model.port(end.instanceName, end.portName);
    if (!rtc || !port)
        return nullptr;
    for (const Profile::RtcDataPort &candidate : rtc->dataPorts) {
        if (candidate.name == port->profileName)
            return &candidate;
    }
    return nullptr;
}

/// The values both ports offer, in `all`'s order; `all` when a port does not say.
QStringList intersect(const QStringList &all, const QStringList &a, const QStringList &b)
{
    QStringList result;
    for (const QString &value : all) {
        if ((a.isEmpty() || a.contains(value)) && (b.isEmpty() || b.contains(value)))
            result << value;
    }
    // Values only the ports know (a new interface type) are offered too.
    for (const QString &value : a) {
        if (!all.contains(value) && (b.isEmpty() || b.contains(value)))
            result << value;
    }
    return result.isEmpty() ? all : result;
}

/// The RTC profiles a drag carries: the repository's mime data (one profile file path per line,
/// or the profile's text itself), or profile files dragged from a file manager.
QList<QPair<Profile::RtcProfile, QString>> droppedProfiles(const QMimeData *mime)
{
    QStringList paths;
    if (mime->hasFormat(RtcRepository::MimeType)) {
        const QByteArray data = mime->data(RtcRepository::MimeType);
        Profile::Diagnostics diagnostics;
        const std::optional<Profile::LoadedProfile> inline_
            = Profile::loadProfileData(data, QString(), &diagnostics);
        if (inline_ && inline_->rtc)
            return {{*inline_->rtc, QString()}};
        paths = QString::fromUtf8(data).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    }
    for (const QUrl &url : mime->urls()) {
        if (url.isLocalFile())
            paths << url.toLocalFile();
    }
    QList<QPair<Profile::RtcProfile, QString>> profiles;
    for (const QString &path : std::as_const(paths)) {
        Profile::Diagnostics diagnostics;
        const std::optional<Profile::LoadedProfile> loaded
            = Profile::loadProfileFile(path.trimmed(), &diagnostics);
        if (loaded && loaded->rtc)
            profiles.append({*loaded->rtc, QFileInfo(path.trimmed()).absoluteFilePath()});
    }
    return profiles;
}

bool carriesProfiles(const QMimeData *mime)
{
    return mime->hasFormat(RtcRepository::MimeType) || mime->hasUrls();
}

} // namespace

void SystemView::dragEnterEvent(QDragEnterEvent *event)
{
    if (carriesProfiles(event->mimeData()) && m_scene->undoStack())
        event->acceptProposedAction();
    else
        event->ignore();
}

void SystemView::dragMoveEvent(QDragMoveEvent *event)
{
    if (carriesProfiles(event->mimeData()) && m_scene->undoStack())
        event->acceptProposedAction();
    else
        event->ignore();
}

void SystemView::dropEvent(QDropEvent *event)
{
    const QList<QPair<Profile::RtcProfile, QString>> profiles
        = droppedProfiles(event->mimeData());
    if (profiles.isEmpty()) {
        emit statusMessage(tr("Only RTC profiles can be dropped on a system."));
        event->ignore();
        return;
    }
    QPointF at = mapToScene(event->position().toPoint());
    QStringList added;
    for (const auto &[rtc, path] : profiles) {
        const QString name = m_scene->addComponent(rtc, path, at);
        if (!name.isEmpty())
            added << name;
        at += QPointF(SystemScene::GridSize * 2, SystemScene::GridSize * 2);
    }
    m_scene->selectComponents(added);
    event->acceptProposedAction();
}

ConnectorDialog::Choices SystemView::choicesFor(const ConnectionCheck &check) const
{
    ConnectorDialog::Choices choices;
    const Profile::RtcDataPort *out = rtcPort(*m_scene->model(), check.source);
    const Profile::RtcDataPort *in = rtcPort(*m_scene->model(), check.target);
    const auto values = [](const Profile::RtcDataPort *port,
                           std::optional<QString> Profile::RtcDataPort::*field) {
        return port ? listOf(port->*field) : QStringList();
    };
    choices.interfaceTypes
        = intersect(choices.interfaceTypes, values(out, &Profile::RtcDataPort::interfaceType),
                    values(in, &Profile::RtcDataPort::interfaceType));
    choices.dataflowTypes
        = intersect(choices.dataflowTypes, values(out, &Profile::RtcDataPort::dataflowType),
                    values(in, &Profile::RtcDataPort::dataflowType));
    choices.subscriptionTypes = intersect(choices.subscriptionTypes,
                                          values(out, &Profile::RtcDataPort::subscriptionType),
                                          values(in, &Profile::RtcDataPort::subscriptionType));
    return choices;
}

void SystemView::startRename()
{
    const QStringList selected = m_scene->selectedComponents();
    if (selected.isEmpty() || m_renameEditor)
        return;
    m_renamedInstance = selected.first();
    const ComponentItem *item = m_scene->componentItem(m_renamedInstance);
    const QRect body = mapFromScene(item->mapToScene(item->bodyRect())).boundingRect();
    auto *editor = new RenameEdit(m_renamedInstance, viewport());
    editor->onEscape = [this] { finishRename(false); };
    m_renameEditor = editor;
    m_renameEditor->setObjectName(QStringLiteral("renameEditor"));
    m_renameEditor->setAlignment(Qt::AlignCenter);
    m_renameEditor->setGeometry(body.left(), body.center().y() - 14, body.width(), 24);
    m_renameEditor->selectAll();
    m_renameEditor->show();
    m_renameEditor->setFocus();
    connect(m_renameEditor, &QLineEdit::returnPressed, this, [this] { finishRename(true); });
    connect(m_renameEditor, &QLineEdit::editingFinished, this, [this] { finishRename(true); });
}

void SystemView::finishRename(bool commit)
{
    if (!m_renameEditor)
        return;
    QLineEdit *editor = m_renameEditor;
    m_renameEditor = nullptr;
    const QString newName = editor->text();
    editor->hide();
    editor->deleteLater();
    setFocus();
    if (commit)
        m_scene->renameComponent(m_renamedInstance, newName);
}

} // namespace SystemEditor
