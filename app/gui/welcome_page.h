// WelcomePage: what the main window shows while it has neither a device nor a file — the ways to
// start (connect to a node, open a parameter file, make a new one, try the built-in simulator)
// as buttons, so a new user is never left in front of an empty tree. GUI thread only.
#pragma once

#include <QWidget>

class QCommandLinkButton;
class QLabel;

namespace vt::app {

class WelcomePage : public QWidget
{
    Q_OBJECT
public:
    explicit WelcomePage(QWidget *parent = nullptr);

    QCommandLinkButton *connectButton() const { return m_connect; }
    QCommandLinkButton *openButton() const { return m_open; }
    QCommandLinkButton *newButton() const { return m_new; }
    QCommandLinkButton *simulatorButton() const { return m_simulator; }

signals:
    void connectRequested();
    void openRequested();
    void newRequested();
    void simulatorRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QLabel *m_title = nullptr;
    QLabel *m_intro = nullptr;
    QCommandLinkButton *m_connect = nullptr;
    QCommandLinkButton *m_open = nullptr;
    QCommandLinkButton *m_new = nullptr;
    QCommandLinkButton *m_simulator = nullptr;
};

} // namespace vt::app
