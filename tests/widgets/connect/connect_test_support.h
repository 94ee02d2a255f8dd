// Helpers for the connect tests: children by object name, the OK button of a dialog; the
// simulator rig and bounded waits come from tests/support.
#pragma once

#include "sim_rig.h"

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QPushButton>
#include <gtest/gtest.h>

namespace vt::test {

template<typename T> T *child(const QObject &parent, const char *name)
{
    T *found = parent.findChild<T *>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << "no child " << name;
    return found;
}

inline bool okEnabled(const QDialog &dialog)
{
    auto *buttons = dialog.findChild<QDialogButtonBox *>(QStringLiteral("buttons"));
    return buttons && buttons->button(QDialogButtonBox::Ok)->isEnabled();
}

inline void selectData(QComboBox *box, const QVariant &data)
{
    const int index = box->findData(data);
    ASSERT_GE(index, 0) << "no item " << data.toString().toStdString();
    box->setCurrentIndex(index);
}

} // namespace vt::test
