// ChannelChooser: the monitor's "Channels…" dialog — every live value of every connected module
// as a checkable tree (module ▸ rows), so any d-value of any module can go on the plot.
// GUI thread.
#pragma once

#include "model/session/device_access.h"

#include <QDialog>
#include <map>
#include <vector>

class QTreeWidget;
class QLabel;

namespace vt::ui {

using ChannelSelection = std::map<int, std::vector<const dev::ParamMeta *>>; // module -> rows

class ChannelChooser : public QDialog
{
    Q_OBJECT
public:
    // `offered`: the rows each module can show; `selected`: what is on the plot now.
    ChannelChooser(const std::vector<model::ModuleInfo> &modules, const ChannelSelection &offered,
                   const ChannelSelection &selected, dev::Language lang, QWidget *parent = nullptr);

    // Checked rows per module (modules without a checked row are absent), in dictionary order.
    ChannelSelection selection() const;
    // Checks exactly `rows` of `module` (tests and presets).
    void setChecked(int module, const std::vector<const dev::ParamMeta *> &rows);
    QTreeWidget *tree() const { return m_tree; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QTreeWidget *m_tree = nullptr;
    QLabel *m_hint = nullptr;
};

} // namespace vt::ui
