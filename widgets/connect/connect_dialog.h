// ConnectDialog: File ▸ Connect — choose the link (serial, TCP, CAN, HART, built-in simulator)
// and get the model::ConnectionSpec that model::Connection::create() builds it from. OK stays
// disabled, with the reason shown, while the fields do not describe a connection. With a
// QSettings the dialog opens on the last used kind with every kind's last fields, and remembers
// the accepted spec (ConnectionMemory).
#pragma once

#include "model/session/connection.h"

#include <QDialog>
#include <vector>

class QDialogButtonBox;
class QLabel;
class QSettings;
class QTabWidget;

namespace vt::dev {
class DictionarySet;
}

namespace vt::ui {

class ConnectPage;

class ConnectDialog : public QDialog
{
    Q_OBJECT
public:
    // `dictionaries` (the simulator's families) must outlive the dialog; `memory`, when given,
    // is read now and written on accept, and must outlive the dialog too.
    explicit ConnectDialog(const dev::DictionarySet &dictionaries, QSettings *memory = nullptr,
                           QWidget *parent = nullptr);

    // The spec of the chosen kind's fields; meaningful when problem() is empty.
    model::ConnectionSpec spec() const;
    // Shows the page of spec.kind, filled from `spec`.
    void setSpec(const model::ConnectionSpec &spec);
    model::ConnectionKind kind() const;
    void setKind(model::ConnectionKind kind);
    // Why OK is disabled, for people; empty when it is not.
    QString problem() const;

    void accept() override;

protected:
    void changeEvent(QEvent *event) override;

private:
    ConnectPage *page(model::ConnectionKind kind) const;
    ConnectPage *currentPage() const;
    void updateState();
    void retranslate();

    QSettings *m_memory = nullptr;
    QTabWidget *m_tabs = nullptr;
    std::vector<ConnectPage *> m_pages;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace vt::ui
