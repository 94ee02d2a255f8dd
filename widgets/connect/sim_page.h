// SimPage: the built-in simulator (model/session/sim_endpoint.h) — a family the simulator can
// serve (HCS over Modbus / node image, Wandfluh SD7 over HART), its mode, the number of modules
// of an HCS node, and the protocol where the family offers more than one.
#pragma once

#include "widgets/connect/connect_page.h"

class QComboBox;
class QLabel;
class QSpinBox;

namespace vt::dev {
class DictionarySet;
struct Dictionary;
} // namespace vt::dev

namespace vt::ui {

class SimPage : public ConnectPage
{
    Q_OBJECT
public:
    // `dictionaries` must outlive the page.
    explicit SimPage(const dev::DictionarySet &dictionaries, QWidget *parent = nullptr);

    model::ConnectionKind kind() const override { return model::ConnectionKind::Sim; }
    QString title() const override;
    void load(const model::ConnectionSpec &spec) override;
    model::ConnectionSpec spec() const override;
    QString problem() const override;

    // The families offered, in list order.
    std::vector<std::string> families() const;

protected:
    void retranslate() override;

private:
    const dev::Dictionary *dictionary() const;
    void fillForFamily();
    void retranslateChoices();

    const dev::DictionarySet &m_dictionaries;
    QComboBox *m_family = nullptr;
    QComboBox *m_mode = nullptr;
    QSpinBox *m_modules = nullptr;
    QComboBox *m_protocol = nullptr;
    QLabel *m_familyLabel = nullptr;
    QLabel *m_modeLabel = nullptr;
    QLabel *m_modulesLabel = nullptr;
    QLabel *m_protocolLabel = nullptr;
};

} // namespace vt::ui
