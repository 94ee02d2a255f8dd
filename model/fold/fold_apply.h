// FoldApply: puts a FoldPlan onto a live node — each module's bus options
// written with WriteJob (range-checked, paced, read back), DMA addresses (E22) changed in an order
// that never gives two modules the same address, then a scan that identifies every address the
// plan expects. For a point-to-point serial line the wizard runs one module at a time
// (applyModule) while the technician moves the cable.
// Owner: the fold wizard or a test; GUI thread (the access's), which must outlive the job.
#pragma once

#include "model/fold/fold_plan.h"
#include "model/sentence.h"
#include "model/session/device_access.h"
#include "model/session/write_record.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace vt::model {

class WriteJob;

enum class FoldApplyState { Pending, Running, Done, Failed };

struct FoldApplyModule
{
    int current = 0; // where the module answers before the apply (scan / point-to-point unit)
    int target = 0;  // where the plan wants it (DMA E22; OPAT SADR, set by the rotary switch)
    FoldApplyState state = FoldApplyState::Pending;
    std::optional<ModuleInfo> info; // what identify found at `current`
    std::vector<WriteItem> writes;  // the options, then E22 when it changes
    bool addressWritten =
        false; // E22 changed and read back (at the new address; point-to-point: at the line's unit)
    std::optional<bool> found;   // the closing scan identified a module at `target`
    std::vector<Sentence> notes; // for people: skipped options, what went wrong

    QStringList noteTexts() const; // the notes in the language in force
};

class FoldApply : public QObject
{
    Q_OBJECT
public:
    // `current[i]`: where plan.modules[i] answers now (same length as the plan's modules).
    FoldApply(DeviceAccess &access, FoldPlan plan, std::vector<int> current,
              QObject *parent = nullptr);
    ~FoldApply() override;

    const FoldPlan &plan() const { return m_plan; }
    const std::vector<FoldApplyModule> &modules() const { return m_modules; }
    bool isRunning() const { return m_phase != Phase::Idle; }

    // The whole node over a bus (Modbus TCP gateway, RS485, node image): options of every
    // module, then the address changes, then the scan. finished(ok) at the end.
    void start();
    // One module (point-to-point line: only this one is connected): its options, its address,
    // then identify it at its target address. finished(ok) at the end.
    void applyModule(std::size_t index);
    // Stops after the exchange on the wire; finished(false) follows.
    void cancel();

signals:
    void moduleChanged(int index);
    void message(const QString &text);
    void finished(bool ok);

private:
    enum class Phase { Idle, Options, Addresses, Scan };

    // Starts the option writes over `todo`; guided: one module on a point-to-point line.
    void begin(std::vector<std::size_t> todo, bool guided);
    void nextOptions();
    void identifyThenWrite(std::size_t index);
    void writeOptions(std::size_t index);
    void onOptionsDone(std::size_t index);
    void nextMove();
    // Reads E22 back at `at` (the new address; point-to-point also the line's unit).
    void confirmAddress(std::size_t index, int from, int to, int at);
    void nextScan();
    void finish();
    void fail(std::size_t index, const Sentence &why);
    // A sentence of this class's tr() context, said when shown (notes outlive a language switch).
    static Sentence said(const char *source) { return {staticMetaObject.className(), source}; }
    std::vector<std::size_t> addressChanges() const;
    bool alive(unsigned generation) const
    {
        return generation == m_generation && m_phase != Phase::Idle;
    }

    DeviceAccess &m_access;
    FoldPlan m_plan;
    std::vector<FoldApplyModule> m_modules;
    std::vector<std::size_t> m_todo; // module indexes this run covers
    std::size_t m_cursor = 0;
    struct Move
    {
        std::size_t module;
        int from, to;
    };
    std::vector<Move> m_moves;
    Phase m_phase = Phase::Idle;
    unsigned m_generation = 0;
    bool m_cancelled = false;
    bool m_guided = false; // applyModule(): one module on a point-to-point line
    QPointer<WriteJob> m_job;
    std::vector<QElapsedTimer> m_lastWrite; // per module: since its last write job ended
};

} // namespace vt::model
