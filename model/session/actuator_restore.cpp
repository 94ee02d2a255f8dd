#include "actuator_restore.h"

#include <QTimer>

namespace vt::model {

ActuatorRestore::ActuatorRestore(DeviceAccess &access, std::map<int, std::vector<WriteItem>> plan,
                                 std::map<int, const dev::Dictionary *> dictionaries,
                                 QObject *parent)
    : QObject(parent), m_access(access), m_plan(std::move(plan)),
      m_dictionaries(std::move(dictionaries))
{
}

ActuatorRestore::~ActuatorRestore() = default;

void ActuatorRestore::start()
{
    next();
}

bool ActuatorRestore::complete() const
{
    for (const RestoredRow &r : m_results)
        if (!isOnDevice(r.item.status))
            return false;
    return true;
}

void ActuatorRestore::next()
{
    while (!m_plan.empty()) {
        auto first = m_plan.begin();
        const int module = first->first;
        std::vector<WriteItem> items = std::move(first->second);
        m_plan.erase(first);
        const auto dict = m_dictionaries.find(module);
        if (dict == m_dictionaries.end() || !dict->second) {
            for (WriteItem &item : items) {
                item.status = WriteStatus::NotSent;
                item.reason = Sentence(staticMetaObject.className(),
                                       QT_TR_NOOP("module %1 is not on the node"))
                                  .arg(module);
                m_results.push_back({module, std::move(item)});
            }
            continue;
        }
        WriteOptions options;
        options.skipUnchanged = false; // `before` is the tool's own value: always send
        m_job = std::make_unique<WriteJob>(m_access, module, *dict->second, std::move(items),
                                           AuditOrigin::Restore, options);
        connect(m_job.get(), &WriteJob::finished, this, [this, module](bool) {
            for (const WriteItem &item : m_job->items())
                m_results.push_back({module, item});
            // The job is still on the stack: next module from the event loop.
            QTimer::singleShot(0, this, [this] {
                m_job.reset();
                next();
            });
        });
        m_job->start();
        return;
    }
    QTimer::singleShot(0, this, [this] { emit finished(complete()); });
}

} // namespace vt::model
