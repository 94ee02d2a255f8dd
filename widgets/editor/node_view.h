// NodeView: the node and its modules — address, identity, version, mode, state word, online, the
// device's own texts (HART tag, long tag, descriptor, date, message) and, for the Wandfluh
// profiles, "Device local" and "Device mode" — from a scan of the connected node or from the open
// file. Selecting a module tells the editor; the context menu of an online Wandfluh module asks
// for a device state, a fault reset, or another device local / device mode.
#pragma once

#include <QTreeWidget>

class QMenu;

namespace vt::model {
class ParameterDocument;
}

namespace vt::ui {

class NodeView : public QTreeWidget
{
    Q_OBJECT
public:
    explicit NodeView(model::ParameterDocument &document, QWidget *parent = nullptr);

    // The node's description ("sim dma-pn-v51 ×3, modbus-tcp …" or the file name).
    void setNodeText(const QString &text);

signals:
    void moduleActivated(int module);
    // The context menu of an online Wandfluh ED1/SD1 or SD7: the person chose a device state
    // (ED1/SD1 manual and HART-7 manual §4.2.2) — `controlWord` is its db_ControlWord — or
    // "reset fault", or a value of db_Local / db_DeviceMode (`row`, raw `value`).
    void controlWordRequested(int module, quint16 controlWord);
    void resetFaultRequested(int module);
    void valueRequested(int module, const QString &row, double value);

protected:
    void changeEvent(QEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    void rebuild();
    void retranslate();
    void addModeMenus(QMenu &menu, int module);

    model::ParameterDocument &m_document;
    QString m_nodeText;
};

} // namespace vt::ui
