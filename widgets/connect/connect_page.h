// ConnectPage: one link kind's page of the connect dialog — its fields, the ConnectionSpec they
// describe and why they do not describe a usable one yet.
#pragma once

#include "model/session/connection.h"

#include <QString>
#include <QWidget>

namespace vt::ui {

class ConnectPage : public QWidget
{
    Q_OBJECT
public:
    using QWidget::QWidget;

    virtual model::ConnectionKind kind() const = 0;
    // The tab label, in the current language.
    virtual QString title() const = 0;
    // Fills the fields from a spec of this page's kind (a remembered one).
    virtual void load(const model::ConnectionSpec &spec) = 0;
    // The spec the fields describe; meaningful only when problem() is empty.
    virtual model::ConnectionSpec spec() const = 0;
    // Why the fields do not describe a connection, for people; empty when they do.
    virtual QString problem() const = 0;

signals:
    void changed();

protected:
    void changeEvent(QEvent *event) override;
    virtual void retranslate() = 0;
};

} // namespace vt::ui
