#include "new_file_dialog.h"

#include "dict/dictionary.h"
#include "widgets/connect/language_text.h"
#include "widgets/number_box.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QStringList>
#include <QVBoxLayout>
#include <algorithm>

namespace vt::ui {

namespace {

const char *const kOpatMaster = "34";

} // namespace

NewFileDialog::NewFileDialog(const dev::DictionarySet &dictionaries, QWidget *parent)
    : QDialog(parent), m_dictionaries(dictionaries)
{
    auto *layout = new QVBoxLayout(this);
    auto *form = new QFormLayout;
    layout->addLayout(form);
    m_family = new QComboBox(this);
    m_family->setObjectName(QStringLiteral("family"));
    for (const std::string &family : m_dictionaries.families())
        m_family->addItem(QString(), QString::fromStdString(family));
    m_familyLabel = new QLabel(this);
    form->addRow(m_familyLabel, m_family);
    m_version = new QComboBox(this);
    m_version->setObjectName(QStringLiteral("version"));
    m_versionLabel = new QLabel(this);
    form->addRow(m_versionLabel, m_version);
    m_mode = new QComboBox(this);
    m_mode->setObjectName(QStringLiteral("mode"));
    m_modeLabel = new QLabel(this);
    form->addRow(m_modeLabel, m_mode);
    m_modules = new WholeNumberBox(this);
    m_modules->setObjectName(QStringLiteral("modules"));
    m_modulesLabel = new QLabel(this);
    form->addRow(m_modulesLabel, m_modules);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("summary"));
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::PlainText);
    layout->addWidget(m_summary);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->setObjectName(QStringLiteral("buttons"));
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    connect(m_family, &QComboBox::currentIndexChanged, this, &NewFileDialog::fillForFamily);
    connect(m_version, &QComboBox::currentIndexChanged, this, &NewFileDialog::updateSummary);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &NewFileDialog::updateSummary);
    connect(m_modules, &QSpinBox::valueChanged, this, [this] {
        updateVersionLock();
        updateSummary();
    });
    fillForFamily();
    retranslate();
}

const dev::Dictionary *NewFileDialog::dictionary() const
{
    return m_dictionaries.find(m_family->currentData().toString().toStdString());
}

bool NewFileDialog::setFamily(const std::string &family)
{
    const int index = m_family->findData(QString::fromStdString(family));
    if (index < 0)
        return false;
    m_family->setCurrentIndex(index);
    return true;
}

model::NewFileChoice NewFileDialog::choice() const
{
    model::NewFileChoice c;
    c.dictionary = dictionary();
    c.version = m_version->currentData().toString().toStdString();
    c.mode = m_mode->currentData().toString().toStdString();
    bool numeric = false;
    const int raw = m_mode->currentData().toString().toInt(&numeric);
    c.modeRaw = numeric ? raw : -1;
    c.modules = m_modules->value();
    return c;
}

void NewFileDialog::fillForFamily()
{
    const dev::Dictionary *dict = dictionary();
    {
        const QSignalBlocker blockVersion(m_version);
        const QSignalBlocker blockMode(m_mode);
        const QSignalBlocker blockModules(m_modules);
        m_version->clear();
        m_mode->clear();
        if (dict) {
            // Newest first: a new file is most likely for current hardware (and the OPAT master
            // V34 before its slaves' V31).
            std::vector<std::string> versions = dict->versions;
            std::sort(
                versions.begin(), versions.end(), [](const std::string &a, const std::string &b) {
                    return QString::fromStdString(a).toInt() > QString::fromStdString(b).toInt();
                });
            for (const std::string &v : versions)
                m_version->addItem(QString(), QString::fromStdString(v));
            for (const std::string &mode : dict->modes)
                m_mode->addItem(QString(), QString::fromStdString(mode));
        }
        m_modules->setRange(1, dict ? model::maxModules(*dict) : 1);
        m_modules->setValue(1);
    }
    m_version->setEnabled(m_version->count() > 1);
    m_mode->setEnabled(m_mode->count() > 1);
    m_modules->setEnabled(m_modules->maximum() > 1);
    m_modulesLabel->setEnabled(m_modules->isEnabled());
    retranslate();
    updateVersionLock();
    updateSummary();
}

void NewFileDialog::updateVersionLock()
{
    // A node with CAN slaves is led by an OPAT master, which runs V34 (OPAT manual §1.2).
    const dev::Dictionary *dict = dictionary();
    const bool opatNode = dict && dict->family == "opat" && m_modules->value() > 1;
    if (opatNode) {
        const int master = m_version->findData(QString::fromLatin1(kOpatMaster));
        if (master >= 0)
            m_version->setCurrentIndex(master);
    }
    m_version->setEnabled(!opatNode && m_version->count() > 1);
}

void NewFileDialog::updateSummary()
{
    const model::NewFileChoice c = choice();
    const bool ok = c.valid();
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(ok);
    if (!ok) {
        m_summary->setText(tr("This combination cannot be a device."));
        return;
    }
    const QLocale locale;
    QStringList places;
    for (const model::ModulePlace &place : model::modulePlaces(c)) {
        places << (place.version.empty() ? tr("address %1").arg(locale.toString(place.address))
                                         : tr("address %1 (V%2)")
                                               .arg(locale.toString(place.address),
                                                    QString::fromStdString(place.version)));
    }
    m_summary->setText(
        tr("%n module(s): %1. Values start at the dictionary's defaults.", nullptr, c.modules)
            .arg(places.join(QStringLiteral(", "))));
}

void NewFileDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        updateSummary();
    }
    QDialog::changeEvent(event);
}

void NewFileDialog::retranslate()
{
    setWindowTitle(tr("New parameter file"));
    m_familyLabel->setText(tr("&Device family:"));
    m_familyLabel->setBuddy(m_family);
    m_versionLabel->setText(tr("Software &version:"));
    m_versionLabel->setBuddy(m_version);
    m_modeLabel->setText(tr("&Mode:"));
    m_modeLabel->setBuddy(m_mode);
    m_modulesLabel->setText(tr("M&odules:"));
    m_modulesLabel->setBuddy(m_modules);
    for (int i = 0; i < m_family->count(); ++i) {
        const std::string id = m_family->itemData(i).toString().toStdString();
        if (const dev::Dictionary *dict = m_dictionaries.find(id))
            m_family->setItemText(i, familyText(*dict));
    }
    for (int i = 0; i < m_version->count(); ++i)
        m_version->setItemText(i, tr("V%1").arg(m_version->itemData(i).toString()));
    if (m_version->count() == 0)
        m_version->setPlaceholderText(tr("identified from the device"));
    if (const dev::Dictionary *dict = dictionary())
        for (int i = 0; i < m_mode->count(); ++i)
            m_mode->setItemText(i, modeText(*dict, m_mode->itemData(i).toString().toStdString()));
}

} // namespace vt::ui
