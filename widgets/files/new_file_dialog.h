// NewFileDialog: File ▸ New — pick the device family, software version and mode (and the
// number of modules of an HCS node) from the dictionaries; choice() is what newParamFile()
// (new_file.h) turns into a file of dictionary defaults.
#pragma once

#include "model/params/new_file.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QSpinBox;

namespace vt::dev {
class DictionarySet;
}

namespace vt::ui {

class NewFileDialog : public QDialog
{
    Q_OBJECT
public:
    // `dictionaries` must outlive the dialog and the choices it returns.
    explicit NewFileDialog(const dev::DictionarySet &dictionaries, QWidget *parent = nullptr);

    model::NewFileChoice choice() const;
    // Preselects a family (the one of the connected device, say); false when it is not offered.
    bool setFamily(const std::string &family);

protected:
    void changeEvent(QEvent *event) override;

private:
    const dev::Dictionary *dictionary() const;
    void fillForFamily();
    void updateVersionLock();
    void updateSummary();
    void retranslate();

    const dev::DictionarySet &m_dictionaries;
    QComboBox *m_family = nullptr;
    QComboBox *m_version = nullptr;
    QComboBox *m_mode = nullptr;
    QSpinBox *m_modules = nullptr;
    QLabel *m_familyLabel = nullptr;
    QLabel *m_versionLabel = nullptr;
    QLabel *m_modeLabel = nullptr;
    QLabel *m_modulesLabel = nullptr;
    QLabel *m_summary = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace vt::ui
