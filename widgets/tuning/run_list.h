// RunList: the workbench's kept runs — the list (the current run is drawn with its marks, ticked
// ones are overlaid), their numbers, and saving and loading them as run files (tuning_run.h).
// GUI thread; owned by the workbench view, which shows what shownRuns() returns.
#pragma once

#include "model/tuning/tuning_run.h"

#include <QWidget>
#include <memory>
#include <vector>

class QLabel;
class QListWidget;
class QPushButton;

namespace vt::ui {

class RunList : public QWidget
{
    Q_OBJECT
public:
    explicit RunList(QWidget *parent = nullptr);
    ~RunList() override;

    const std::vector<std::unique_ptr<model::TuningRun>> &runs() const { return m_runs; }
    // The number the next run gets.
    int nextNumber() const { return m_nextNumber; }
    // Keeps `run`, makes it the current one; `tickPrevious`: the run before it is overlaid.
    void addRun(std::unique_ptr<model::TuningRun> run, bool tickPrevious = false);
    // The current run first, then the ticked ones.
    std::vector<const model::TuningRun *> shownRuns() const;
    // Save and Load follow the workbench (not while a test runs).
    void setFilesEnabled(bool enabled);

    void saveCurrent();
    void loadRuns();

signals:
    void selectionChanged();
    void statusMessage(const QString &text);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    std::vector<std::unique_ptr<model::TuningRun>> m_runs;
    int m_nextNumber = 1;
    QLabel *m_title = nullptr;
    QListWidget *m_list = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_load = nullptr;
};

} // namespace vt::ui
