// UserGuideDialog: Help ▸ User Guide — a short guide inside the application, in the UI language
// (what each window is for, the trust rules, where files go). The text is Markdown kept in the
// resources (resources/guide/user-guide.{en,de}.md) and shown again in the other language on a
// switch. GUI thread only.
#pragma once

#include <QDialog>

class QTextBrowser;

namespace vt::ui {

class UserGuideDialog : public QDialog
{
    Q_OBJECT
public:
    explicit UserGuideDialog(QWidget *parent = nullptr);

    QTextBrowser *browser() const { return m_browser; }
    // The guide's Markdown in the UI language ("en" or "de"); empty if the resource is missing.
    static QString guideText(const QString &language);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QTextBrowser *m_browser = nullptr;
};

} // namespace vt::ui
