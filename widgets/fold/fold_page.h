// Base of the fold wizard pages: access to the wizard's plan and a retranslate() hook called on
// QEvent::LanguageChange.
#pragma once

#include <QEvent>
#include <QWizardPage>

namespace vt::ui {

class FoldWizard;

class FoldPage : public QWizardPage
{
    Q_OBJECT
public:
    using QWizardPage::QWizardPage;

protected:
    FoldWizard *fold() const;
    virtual void retranslate() = 0;
    void changeEvent(QEvent *event) override
    {
        if (event->type() == QEvent::LanguageChange)
            retranslate();
        QWizardPage::changeEvent(event);
    }
};

} // namespace vt::ui
