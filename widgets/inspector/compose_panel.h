// ComposePanel: the inspector's composer — build a request from fields (HCS CMD 3/6/15, Modbus
// FC 3/6, DSP-408 PKW, HART, CANopen SDO) with the codecs' encoders, see its bytes and fields,
// and send it on the current link as a raw transaction. Writes ask for confirmation first, naming
// the parameter and its old → new value where the module's dictionary knows the address; once
// answered, that parameter is read back so the device image (the editor's Device column) follows.
// A frame the link cannot carry keeps Send disabled and says why.
#pragma once

#include "inspect/compose.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "model/session/write_record.h"

#include <QPointer>
#include <QWidget>
#include <functional>
#include <map>
#include <optional>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace vt::model {
class Connection;
}

namespace vt::ui {

class FrameDetail;

class ComposePanel : public QWidget
{
    Q_OBJECT
public:
    explicit ComposePanel(QWidget *parent = nullptr);

    // The link to send on; not owned (QPointer: a destroyed connection disables Send).
    // `modules`: the identified modules, whose dictionaries name a written address.
    void setConnection(vt::model::Connection *connection,
                       const std::vector<vt::model::ModuleInfo> &modules = {});
    void clearConnection();
    // Asked before a write leaves; returns true to send. Default: a QMessageBox question.
    void setConfirmation(std::function<bool(const QString &question)> confirm);

    void setKind(vt::dev::inspect::ComposeKind kind);
    vt::dev::inspect::ComposeKind kind() const;
    // Field editors by name: "tadr", "sadr", "unit", "transaction", "id", "count", "value",
    // "modules" ("CTRL,V1,V2; …"), "ind", "pnu", "instance", "poll", "deviceType", "deviceId",
    // "command", "data", "node", "index", "subindex". Numbers: decimal (locale) or 0x hex.
    void setFieldText(const QString &name, const QString &text);
    void setModbusTcp(bool tcp);
    void setWidth(int bytes);
    void setFamily(vt::dev::hcs::Family family);

    const std::optional<vt::dev::inspect::ComposedFrame> &composed() const { return m_frame; }
    QString problem() const; // why nothing could be composed; empty when composed
    bool canSend() const;
    QString sendBlockedReason() const; // empty when Send is enabled
    FrameDetail *detail() const { return m_detail; }

public slots:
    void rebuild();
    // Sends the composed frame (after confirmation for writes); false when nothing went out.
    bool send();

signals:
    // The raw exchange ended: outcome text for people; answered = the device replied.
    void sendFinished(const QString &outcome, bool answered);
    // A write of a known parameter was answered: for the tuning journal.
    void wrote(int module, const std::vector<vt::model::WriteItem> &items);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateVisibility();
    void updateSend();
    std::optional<long long> number(const QString &name, QString *problem) const;
    int moduleOf(const vt::dev::inspect::ComposeSpec &spec) const;
    const vt::dev::Dictionary *dictionaryOf(int address) const;
    // A field's label as shown, without its colon ("Count"); empty for an unknown field.
    QString labelText(const QString &name) const;
    // The dictionary row a write frame addresses on its module; null when none is known.
    const vt::dev::ParamMeta *writtenRow(const vt::dev::inspect::ComposeSpec &spec) const;

    QPointer<vt::model::Connection> m_connection;
    std::function<bool(const QString &)> m_confirm;
    std::vector<vt::model::ModuleInfo> m_modules;
    QComboBox *m_kind;
    QComboBox *m_familyBox;
    QComboBox *m_widthBox;
    QCheckBox *m_tcp;
    QFormLayout *m_form;
    std::map<QString, QLineEdit *> m_edits;
    std::map<QString, QLabel *> m_labels;
    QLabel *m_bytes;
    QLabel *m_problem;
    QLabel *m_sendReason;
    QLabel *m_result;
    std::function<QString()> m_resultText; // what m_result shows, in the language of now
    QPushButton *m_send;
    FrameDetail *m_detail;
    std::optional<vt::dev::inspect::ComposedFrame> m_frame;
    vt::dev::inspect::ComposeSpec m_spec;
    QString m_problemText;
    bool m_busy = false;
};

} // namespace vt::ui
