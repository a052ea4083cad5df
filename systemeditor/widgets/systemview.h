// SPDX-License-Identifier: MIT
#pragma once

#include "connectorsettings.h"
#include "connectordialog.h"
#include "serviceconnectorsettings.h"
#include "systemmodel.h"

#include <QGraphicsView>

#include <functional>
#include <optional>

class QLineEdit;

namespace SystemEditor {

class SystemScene;
struct ConnectionCheck;

/**
 * The view of a system's canvas: zoom (Ctrl+wheel, +/-/0 keys, fit), pan (middle button or
 * space + drag), rubber-band selection, arrow keys moving the selection, inline renaming (F2),
 * finding a component, dropping RTC profiles from the repository, and the connector dialog for
 * new and edited connectors.
 *
 * The dialog is asked through a replaceable function, so that tests and scripts can answer it.
 */
class SystemView : public QGraphicsView
{
    Q_OBJECT

public:
    /**
     * Asks for a data connector's settings: gets the proposed settings and the choices to offer,
     * returns the accepted settings or nothing when cancelled. The default shows a
     * ConnectorDialog.
     */
    using ConnectorEditor = std::function<std::optional<ConnectorSettings>(
        const ConnectorSettings &proposed, const ConnectorDialog::Choices &choices)>;

    /**
     * Asks for a service connector's settings (name, interface mapping), showing how the two
     * ports' interfaces pair up; returns them or nothing when cancelled. The default shows a
     * ServiceConnectorDialog.
     */
    using ServiceConnectorEditor = std::function<std::optional<ServiceConnectorSettings>(
        const ServiceConnectorSettings &proposed, const ServicePortSide &source,
        const ServicePortSide &target)>;

    explicit SystemView(SystemScene *scene, QWidget *parent = nullptr);

    SystemScene *systemScene() const { return m_scene; }
    void setConnectorEditor(ConnectorEditor editor) { m_connectorEditor = std::move(editor); }
    void setServiceConnectorEditor(ServiceConnectorEditor editor)
    {
        m_serviceConnectorEditor = std::move(editor);
    }

    /// The current scale (1 = 100 %).
    qreal zoomFactor() const;
    void setZoomFactor(qreal factor);
    void zoomIn();
    void zoomOut();
    void resetZoom();
    /// Shows the whole diagram (never zooming in beyond 100 %).
    void fitToDiagram();

    /// Selects and shows the first component whose instance name contains `text` (any case);
    /// false when there is none.
    bool findComponent(const QString &text);
    /// Starts editing the instance name of the (first) selected component in place.
    void startRename();
    /// The inline editor while renaming, else null.
    QLineEdit *renameEditor() const { return m_renameEditor; }
    /// Asks for settings of the connector `check` describes and adds it when accepted.
    void requestConnection(const ConnectionCheck &check);
    /// Opens the connector dialog for an existing connector; edits it when accepted.
    void editConnector(const QString &connectorId);

    static constexpr qreal MinimumZoom = 0.1;
    static constexpr qreal MaximumZoom = 4.0;

signals:
    void zoomChanged(qreal factor);
    /// A short message for the status bar (why a connection was refused, …).
    void statusMessage(const QString &message);

protected:
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dragMoveEvent(QDragMoveEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void growSceneRect();
    void showRefusal(const QString &reason);
    void nudgeSelection(const QPointF &delta);
    void finishRename(bool commit);
    ConnectorDialog::Choices choicesFor(const ConnectionCheck &check) const;
    void requestServiceConnection(const ConnectionCheck &check);
    void editServiceConnector(const QString &connectorId);
    ServicePortSide serviceSide(const ConnectorEnd &end) const;

    SystemScene *m_scene;
    ConnectorEditor m_connectorEditor;
    ServiceConnectorEditor m_serviceConnectorEditor;
    QLineEdit *m_renameEditor = nullptr;
    QString m_renamedInstance;
    bool m_spaceHeld = false;
    bool m_panning = false;
    QPoint m_panStart;
};

} // namespace SystemEditor
