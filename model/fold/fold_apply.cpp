#include "model/fold/fold_apply.h"

#include "core/version.h"
#include "core/vt_assert.h"
#include "model/fold/fold_apply_moves.h"
#include "model/session/write_job.h"

#include <QTimer>
#include <algorithm>

namespace vt::model {

namespace {

// DMA Profinet manual §1.5 / DMA Profibus Anleitung §1.5: E22 1..32.
constexpr int kLowestAddress = 1;
constexpr int kHighestAddress = 32;

} // namespace

FoldApply::FoldApply(DeviceAccess &access, FoldPlan plan, std::vector<int> current, QObject *parent)
    : QObject(parent), m_access(access), m_plan(std::move(plan))
{
    for (std::size_t i = 0; i < m_plan.modules.size(); ++i) {
        FoldApplyModule m;
        m.target = m_plan.modules[i].address;
        m.current = i < current.size() ? current[i] : m.target;
        m_modules.push_back(m);
        m_lastWrite.emplace_back();
    }
}

FoldApply::~FoldApply()
{
    ++m_generation;
    if (m_job && m_job->isRunning()) {
        // WriteJob's session callbacks hold it: it must outlive its exchange on the wire, so it
        // is let go and deletes itself when it stops.
        m_job->setParent(nullptr);
        connect(m_job, &WriteJob::finished, m_job, &QObject::deleteLater);
        m_job->cancel();
    }
}

void FoldApply::start()
{
    if (isRunning())
        return;
    std::vector<std::size_t> all;
    for (std::size_t i = 0; i < m_modules.size(); ++i)
        all.push_back(i);
    begin(std::move(all), false);
}

void FoldApply::applyModule(std::size_t index)
{
    if (isRunning() || index >= m_modules.size())
        return;
    begin({index}, true);
}

void FoldApply::begin(std::vector<std::size_t> todo, bool guided)
{
    m_todo = std::move(todo);
    m_guided = guided;
    m_cancelled = false;
    ++m_generation;
    m_phase = Phase::Options;
    m_cursor = 0;
    QTimer::singleShot(0, this, [this, g = m_generation] {
        if (alive(g))
            nextOptions();
    });
}

void FoldApply::cancel()
{
    if (!isRunning())
        return;
    m_cancelled = true;
    if (m_job)
        m_job->cancel(); // its finished() ends the run
    else
        finish();
}

QStringList FoldApplyModule::noteTexts() const
{
    QStringList texts;
    for (const Sentence &note : notes)
        texts << note.text();
    return texts;
}

void FoldApply::fail(std::size_t index, const Sentence &why)
{
    VT_ASSERT(index < m_modules.size(), return );
    FoldApplyModule &m = m_modules[index];
    m.state = FoldApplyState::Failed;
    m.notes.push_back(why);
    emit message(why.text());
    emit moduleChanged(static_cast<int>(index));
}

void FoldApply::nextOptions()
{
    if (m_cancelled) {
        finish();
        return;
    }
    if (m_cursor >= m_todo.size()) {
        m_phase = Phase::Addresses;
        m_moves.clear();
        std::vector<std::size_t> changing = addressChanges();
        std::vector<AddressChange> changes;
        for (std::size_t index : changing)
            changes.push_back({m_modules[index].current, m_modules[index].target});
        // The other modules of the node keep their addresses and must not be landed on.
        for (std::size_t i = 0; i < m_modules.size(); ++i)
            if (std::find(changing.begin(), changing.end(), i) == changing.end() &&
                m_todo.size() > 1)
                changes.push_back({m_modules[i].current, m_modules[i].current});
        const auto moves = planAddressMoves(changes, kLowestAddress, kHighestAddress);
        if (!moves) {
            emit message(
                tr("The address changes cannot be ordered: two modules would need the same "
                   "address."));
            for (std::size_t index : changing)
                fail(index, said(QT_TR_NOOP("Address not changed.")));
        } else {
            for (const AddressMove &move : *moves)
                m_moves.push_back(
                    {changing[static_cast<std::size_t>(move.module)], move.from, move.to});
        }
        m_cursor = 0;
        nextMove();
        return;
    }
    identifyThenWrite(m_todo[m_cursor]);
}

void FoldApply::identifyThenWrite(std::size_t index)
{
    FoldApplyModule &m = m_modules[index];
    m.state = FoldApplyState::Running;
    m.notes.clear();
    m.found.reset();
    m.addressWritten = false;
    emit moduleChanged(static_cast<int>(index));
    emit message(tr("Module %1: identifying at address %2 …").arg(index + 1).arg(m.current));
    m_access.identify(m.current, [this, index, g = m_generation,
                                  self = QPointer<FoldApply>(this)](const IdentifyResult &result) {
        if (!self || !alive(g))
            return;
        if (!result.ok || !result.module.dictionary) {
            fail(index, said(QT_TR_NOOP("Module %1: no module answers at address %2 (%3)."))
                            .arg(index + 1)
                            .arg(m_modules[index].current)
                            .arg(result.message));
            ++m_cursor;
            nextOptions();
            return;
        }
        FoldApplyModule &mod = m_modules[index];
        mod.info = result.module;
        const FoldModule &planned = m_plan.modules[index];
        const int version = dev::majorVersionNumber(result.module.identification.version);
        if (planned.version != 0 && version != 0 && version != planned.version)
            mod.notes.push_back(said(QT_TR_NOOP("Software V%1 found, the plan says V%2."))
                                    .arg(version)
                                    .arg(planned.version));
        if (planned.mode != 0 && result.module.mode >= 0 && result.module.mode != planned.mode)
            mod.notes.push_back(said(QT_TR_NOOP("Mode %1 found, the plan says mode %2."))
                                    .arg(result.module.mode)
                                    .arg(planned.mode));
        writeOptions(index);
    });
}

void FoldApply::writeOptions(std::size_t index)
{
    FoldApplyModule &m = m_modules[index];
    const dev::Dictionary &dictionary = *m.info->dictionary;
    const FoldModule &planned = m_plan.modules[index];
    std::vector<WriteItem> items;
    for (const std::string &name : foldOptionNames(m_plan.node, index)) {
        const std::optional<int> value = foldOption(planned.options, name);
        if (!value)
            continue;
        const dev::ParamMeta *row = dictionary.find(name);
        // Rows name major versions ("34"); the module reports "34.03".
        const std::string major =
            std::to_string(dev::majorVersionNumber(m.info->identification.version));
        if (!row || !row->appliesTo(major, m.info->identification.mode)) {
            m.notes.push_back(
                said(QT_TR_NOOP("%1 does not exist on this module's software; not written."))
                    .arg(QString::fromStdString(name)));
            continue;
        }
        WriteItem item;
        item.row = row;
        item.value = static_cast<double>(*value);
        items.push_back(item);
    }
    if (items.empty()) {
        onOptionsDone(index);
        return;
    }
    std::vector<const dev::ParamMeta *> rows;
    for (const WriteItem &item : items)
        if (item.row->readable())
            rows.push_back(item.row);
    emit message(tr("Module %1: writing %2 option(s) …").arg(index + 1).arg(items.size()));
    // Read first so that values already right are not written again (EEPROM wear; the record
    // shows "unchanged").
    m_access.read(
        m.current, rows, Priority::User,
        [this, index, items, g = m_generation,
         self = QPointer<FoldApply>(this)](const ReadResult &read) mutable {
            if (!self || !alive(g))
                return;
            for (const RowValue &value : read.values)
                for (WriteItem &item : items)
                    if (item.row == value.row)
                        item.before = value.value;
            FoldApplyModule &mod = m_modules[index];
            auto *job = new WriteJob(m_access, mod.current, *mod.info->dictionary, std::move(items),
                                     AuditOrigin::Fold, {}, this);
            m_job = job;
            connect(job, &WriteJob::finished, this, [this, index, job, g](bool) {
                job->deleteLater();
                m_job = nullptr;
                if (!alive(g))
                    return;
                FoldApplyModule &done = m_modules[index];
                done.writes = job->items();
                m_lastWrite[index].start();
                for (const WriteItem &item : done.writes) {
                    if (isOnDevice(item.status))
                        continue;
                    const QString name = QString::fromStdString(item.row ? item.row->name : "");
                    Sentence why = writeReason(item);
                    if (why.isEmpty())
                        why = writeStatusSentence(item.status);
                    // "E17 is not writable" names the row already; "out of range" does not.
                    done.notes.push_back(why.text().startsWith(name)
                                             ? why
                                             : said(QT_TR_NOOP("%1: %2")).arg(name).arg(why));
                }
                onOptionsDone(index);
            });
            job->start();
        });
}

void FoldApply::onOptionsDone(std::size_t index)
{
    FoldApplyModule &m = m_modules[index];
    const bool allOn = std::all_of(m.writes.begin(), m.writes.end(),
                                   [](const WriteItem &item) { return isOnDevice(item.status); });
    if (!allOn)
        m.state = FoldApplyState::Failed;
    emit moduleChanged(static_cast<int>(index));
    ++m_cursor;
    nextOptions();
}

std::vector<std::size_t> FoldApply::addressChanges() const
{
    std::vector<std::size_t> changing;
    for (std::size_t index : m_todo) {
        const FoldApplyModule &m = m_modules[index];
        if (m.current != m.target && m.state != FoldApplyState::Failed && m.info)
            changing.push_back(index);
    }
    return changing;
}

void FoldApply::nextMove()
{
    if (m_cancelled) {
        finish();
        return;
    }
    if (m_cursor >= m_moves.size()) {
        m_phase = Phase::Scan;
        m_cursor = 0;
        nextScan();
        return;
    }
    const Move move = m_moves[m_cursor];
    FoldApplyModule &m = m_modules[move.module];
    const dev::ParamMeta *e22 = m.info->dictionary->find("E22");
    if (m_plan.node == FoldNode::Opat || !e22 || !e22->writable()) {
        // OPAT manual §1.4: a CAN slave's address is its rotary switch; software cannot change it.
        fail(move.module,
             said(QT_TR_NOOP("Module %1 answers at address %2: set its rotary switch to %3."))
                 .arg(move.module + 1)
                 .arg(move.from)
                 .arg(m.target));
        ++m_cursor;
        nextMove();
        return;
    }
    // DMA Profinet manual §3.4.1: ≥ 30 ms between writes to one module. WriteJob paces within a
    // job; this is the gap since the module's previous job.
    const int pacing = m.info->dictionary->writePacingMs;
    if (m_lastWrite[move.module].isValid() && m_lastWrite[move.module].elapsed() < pacing) {
        const int wait = pacing - static_cast<int>(m_lastWrite[move.module].elapsed()) + 1;
        m_lastWrite[move.module].invalidate();
        QTimer::singleShot(wait, this, [this, g = m_generation] {
            if (alive(g))
                nextMove();
        });
        return;
    }
    emit message(
        tr("Module %1: address %2 → %3 …").arg(move.module + 1).arg(move.from).arg(move.to));
    WriteItem item;
    item.row = e22;
    item.value = static_cast<double>(move.to);
    item.before = static_cast<double>(move.from);
    WriteOptions options;
    // The module answers at the new address as soon as E22 is written; the read-back at the old
    // one would time out, so confirmAddress() reads it back where it now is.
    options.verify = false;
    auto *job = new WriteJob(m_access, move.from, *m.info->dictionary, {item}, AuditOrigin::Fold,
                             options, this);
    m_job = job;
    connect(job, &WriteJob::finished, this, [this, job, move, g = m_generation](bool) {
        job->deleteLater();
        m_job = nullptr;
        if (!alive(g))
            return;
        const WriteItem result = job->items().front();
        FoldApplyModule &mod = m_modules[move.module];
        m_lastWrite[move.module].start();
        if (result.status == WriteStatus::Uncertain || isOnDevice(result.status)) {
            // Uncertain: the acknowledge may have come from the new address only; look there.
            confirmAddress(move.module, move.from, move.to, move.to);
            return;
        }
        mod.writes.push_back(result);
        fail(move.module, said(QT_TR_NOOP("Module %1: E22 not written (%2)."))
                              .arg(move.module + 1)
                              .arg(writeReason(result)));
        ++m_cursor;
        nextMove();
    });
    job->start();
}

void FoldApply::confirmAddress(std::size_t index, int from, int to, int at)
{
    FoldApplyModule &m = m_modules[index];
    const dev::ParamMeta *e22 = m.info->dictionary->find("E22");
    m_access.read(
        at, {e22}, Priority::User,
        [this, index, from, to, at, e22, g = m_generation,
         self = QPointer<FoldApply>(this)](const ReadResult &read) {
            if (!self || !alive(g))
                return;
            FoldApplyModule &mod = m_modules[index];
            const bool holds = read.complete() && !read.values.empty() &&
                               dev::rawNumber(read.values.front().value) == to;
            if (!holds && m_guided && at == to) {
                // Point-to-point: the line's unit may reach the module whatever its E22
                // (the connection's unit, ARCHITECTURE.md "Protocol decisions"); read it
                // back there.
                confirmAddress(index, from, to, from);
                return;
            }
            WriteItem item;
            item.row = e22;
            item.value = static_cast<double>(to);
            item.before = static_cast<double>(from);
            if (holds) {
                item.status = WriteStatus::Verified;
                item.readBack = read.values.front().value;
                mod.current = at;
                mod.addressWritten = to == mod.target;
            } else {
                item.status = WriteStatus::Uncertain;
                item.reason = said(QT_TR_NOOP("no answer with E22 = %1 at address %1")).arg(to);
            }
            // A parked module (ring of swaps) has two E22 records; keep them all.
            mod.writes.push_back(item);
            if (item.status != WriteStatus::Verified)
                fail(index, said(QT_TR_NOOP("Module %1: %2.")).arg(index + 1).arg(item.reason));
            else
                emit moduleChanged(static_cast<int>(index));
            ++m_cursor;
            nextMove();
        });
}

void FoldApply::nextScan()
{
    if (m_cancelled) {
        finish();
        return;
    }
    if (m_cursor >= m_todo.size()) {
        finish();
        return;
    }
    const std::size_t index = m_todo[m_cursor];
    // Point-to-point: the module answers at the line's unit (current) once E22 is verified there.
    const int address = m_guided && m_modules[index].addressWritten ? m_modules[index].current
                                                                    : m_modules[index].target;
    emit message(tr("Scan: identifying address %1 …").arg(address));
    m_access.identify(address, [this, index, address, g = m_generation,
                                self = QPointer<FoldApply>(this)](const IdentifyResult &result) {
        if (!self || !alive(g))
            return;
        FoldApplyModule &m = m_modules[index];
        m.found = result.ok;
        if (!result.ok) {
            fail(index, said(QT_TR_NOOP("Scan: no module answers at address %1.")).arg(address));
        } else {
            if (m.info && result.module.identification.family != m.info->identification.family)
                m.notes.push_back(
                    said(QT_TR_NOOP("Scan: address %1 answers as %2, expected %3."))
                        .arg(address)
                        .arg(QString::fromStdString(result.module.identification.family))
                        .arg(QString::fromStdString(m.info->identification.family)));
            if (m.state != FoldApplyState::Failed)
                m.state = FoldApplyState::Done;
            emit moduleChanged(static_cast<int>(index));
        }
        ++m_cursor;
        nextScan();
    });
}

void FoldApply::finish()
{
    bool ok = !m_cancelled;
    for (std::size_t index : m_todo) {
        FoldApplyModule &m = m_modules[index];
        if (m.state == FoldApplyState::Running || m.state == FoldApplyState::Pending) {
            m.state = m_cancelled ? FoldApplyState::Failed : m.state;
            if (m_cancelled)
                m.notes.push_back(said(QT_TR_NOOP("Cancelled.")));
        }
        if (m.state != FoldApplyState::Done)
            ok = false;
    }
    m_phase = Phase::Idle;
    ++m_generation;
    emit message(ok ? tr("Every module is configured and answers at its address.")
                    : tr("The node is not configured as planned; see the modules' notes."));
    emit finished(ok);
}

} // namespace vt::model
