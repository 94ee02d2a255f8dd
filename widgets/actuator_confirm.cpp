#include "actuator_confirm.h"

#include "model/params/parameter_tree_model.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QPushButton>

namespace vt::ui {
namespace {

ActuatorAnswerHook &answerHook()
{
    static ActuatorAnswerHook hook;
    return hook;
}

// The context of this file's sentences in the translation catalogue.
class ActuatorConfirm
{
    Q_DECLARE_TR_FUNCTIONS(vt::ui::ActuatorConfirm)
};

} // namespace

QString actuatorWriteLine(int module, const dev::ParamMeta &row,
                          const std::optional<dev::RawValue> &before, const dev::RawValue &after,
                          dev::Language lang)
{
    return ActuatorConfirm::tr("Module %1: %2 (%3) %4 → %5")
        .arg(module)
        .arg(QString::fromStdString(row.name), QString::fromStdString(row.label.in(lang)),
             before ? model::formatRaw(row, *before, lang) : QStringLiteral("?"),
             model::formatRaw(row, after, lang));
}

void setActuatorAnswerHook(ActuatorAnswerHook hook)
{
    answerHook() = std::move(hook);
}

void confirmActuatorWrites(QWidget *parent, const QStringList &lines, std::function<void()> yes,
                           std::function<void()> no)
{
    if (lines.isEmpty()) {
        yes();
        return;
    }
    if (answerHook()) {
        if (answerHook()(lines))
            yes();
        else if (no)
            no();
        return;
    }
    auto *box = new QMessageBox(
        QMessageBox::Warning, ActuatorConfirm::tr("This Write Can Move the Valve"),
        ActuatorConfirm::tr("These values drive the actuator. The axis may move as soon as "
                            "they are written.\n\n%1\n\nWrite them?")
            .arg(lines.join(QLatin1Char('\n'))),
        QMessageBox::NoButton, parent);
    box->setObjectName(QStringLiteral("actuatorConfirm"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton *write = box->addButton(ActuatorConfirm::tr("Write"), QMessageBox::AcceptRole);
    QPushButton *cancel = box->addButton(QMessageBox::Cancel);
    box->setDefaultButton(cancel);
    QObject::connect(box, &QMessageBox::finished, box,
                     [box, write, yes = std::move(yes), no = std::move(no)](int) {
                         if (box->clickedButton() == write)
                             yes();
                         else if (no)
                             no();
                     });
    box->open();
}

void askRestoreActuators(QWidget *parent, const QString &when, const QStringList &lines,
                         std::function<void(bool)> answer)
{
    if (lines.isEmpty()) {
        answer(false);
        return;
    }
    if (answerHook()) {
        answer(answerHook()(lines));
        return;
    }
    auto *box = new QMessageBox(
        QMessageBox::Question, ActuatorConfirm::tr("Put Back What Was Changed?"),
        ActuatorConfirm::tr("%1 ValveTune changed values that drive the actuator:\n\n%2\n\n"
                            "Put the original values back?")
            .arg(when, lines.join(QLatin1Char('\n'))),
        QMessageBox::NoButton, parent);
    box->setObjectName(QStringLiteral("actuatorRestore"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton *back = box->addButton(ActuatorConfirm::tr("Put Back"), QMessageBox::AcceptRole);
    box->addButton(ActuatorConfirm::tr("Leave As Is"), QMessageBox::RejectRole);
    box->setDefaultButton(back);
    QObject::connect(
        box, &QMessageBox::finished, box,
        [box, back, answer = std::move(answer)](int) { answer(box->clickedButton() == back); });
    box->open();
}

} // namespace vt::ui
