#include "user_guide_dialog.h"

#include "model/text_language.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QFile>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace vt::ui {

UserGuideDialog::UserGuideDialog(QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("userGuide"));
    m_browser = new QTextBrowser(this);
    m_browser->setOpenExternalLinks(false);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_browser, 1);
    layout->addWidget(buttons);
    resize(760, 640);
    retranslate();
}

QString UserGuideDialog::guideText(const QString &language)
{
    QFile file(QStringLiteral(":/guide/user-guide.%1.md").arg(language));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll());
}

void UserGuideDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void UserGuideDialog::retranslate()
{
    setWindowTitle(tr("ValveTune User Guide"));
    const bool german = model::textLanguage() == dev::Language::German;
    m_browser->setMarkdown(guideText(german ? QStringLiteral("de") : QStringLiteral("en")));
}

} // namespace vt::ui
