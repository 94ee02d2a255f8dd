// Answers every "this write can move the valve" question of the widgets for the length of a test
// and counts the questions (widgets/actuator_confirm.h), so a test proves it was asked.
#pragma once

#include "widgets/actuator_confirm.h"

#include <QList>
#include <QStringList>

namespace vt::test {

struct ActuatorAnswer
{
    explicit ActuatorAnswer(bool yes = true) : answer(yes)
    {
        ui::setActuatorAnswerHook([this](const QStringList &lines) {
            asked.push_back(lines);
            return answer;
        });
    }
    ~ActuatorAnswer() { ui::setActuatorAnswerHook({}); }
    ActuatorAnswer(const ActuatorAnswer &) = delete;
    ActuatorAnswer &operator=(const ActuatorAnswer &) = delete;

    bool answer;
    QList<QStringList> asked;
};

} // namespace vt::test
