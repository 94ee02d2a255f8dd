// DeviceAccess: the one API the model, the CLI and the GUI use to talk to modules, over any
// protocol adapter: identify a module (and pick its dictionary), read rows in the fewest
// exchanges the device allows, write one value. Results arrive through callbacks from the event
// loop. Owner: the connection; same thread as its Session, which must outlive it.
#pragma once

#include "dict/dictionary.h"
#include "dict/identify.h"
#include "model/audit/write_audit.h"
#include "model/session/device_image.h"
#include "model/session/session.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <functional>
#include <memory>
#include <vector>

namespace vt::model {

struct ModuleInfo
{
    int address = 0;
    dev::Identification identification;
    const dev::Dictionary *dictionary = nullptr; // from the DictionarySet; outlives the access
    int versRaw = -1;                            // HCS Vers (ID 0)
    int mode = -1;                               // HCS E00
    dev::LocalText identityText;                 // HART/DSP-408 identity for people
};

struct IdentifyResult
{
    bool ok = false;
    ModuleInfo module;
    Outcome failure; // when !ok and the exchange failed
    // When !ok: why (no answer, unknown device …); when ok: a fallback warning. Either the
    // application's words (through tr()) or the device's or dictionary's, kept in both languages
    // in deviceText; identifyMessage() picks one.
    QString message;
    dev::LocalText deviceText;
};

// The result's message in `lang`: deviceText when there is one, otherwise message.
QString identifyMessage(const IdentifyResult &result, dev::Language lang);

struct RowValue
{
    const dev::ParamMeta *row = nullptr;
    dev::RawValue value;
    // The device answered with a warning (HART common codes such as 14 "status bytes
    // mismatch"): the value arrived and counts; this is what the device said with it.
    int warningCode = 0;
    dev::LocalText warning;
};

struct RowFailure
{
    std::vector<const dev::ParamMeta *> rows;
    Outcome outcome;
};

struct ReadResult
{
    std::vector<RowValue> values;     // in the order the rows were asked for
    std::vector<RowFailure> failures; // exchanges that failed, with their rows
    bool cancelled = false;           // by the handle, or the session ended with the read pending
    bool complete() const { return failures.empty() && !cancelled; }
};

// Read progress: exchanges done of all exchanges planned.
using ReadProgress = std::function<void(int done, int total)>;

class DeviceAccess : public QObject
{
    Q_OBJECT
public:
    // `product` disambiguates HCS versions (identify.h); Unknown when the link does not tell.
    DeviceAccess(Session &session, const dev::DictionarySet &dictionaries,
                 dev::HcsProduct product = dev::HcsProduct::Unknown, QObject *parent = nullptr);
    ~DeviceAccess() override;

    Session &session() const { return m_session; }
    const dev::DictionarySet &dictionaries() const { return m_dictionaries; }
    // Every answer to a read or a write goes into this image. By default the access keeps its
    // own; useImage() points it at one that outlives the connection (the GUI's).
    DeviceImage &image() const { return m_image ? *m_image : m_ownImage; }
    void useImage(DeviceImage &image) { m_image = &image; }

    void identify(int module, std::function<void(const IdentifyResult &)> done);

    // Reads `rows` of `module`; the handle cancels the rest. Rows the protocol cannot address and
    // rows that are not readable are reported as failures with status NotEncodable.
    class ReadHandle;
    std::shared_ptr<ReadHandle> read(int module, std::vector<const dev::ParamMeta *> rows,
                                     Priority priority,
                                     std::function<void(const ReadResult &)> done,
                                     ReadProgress progress = {});

    // Writes one raw value. The caller range-checks first (dev::checkWrite); this does not read
    // back. An acknowledged write is recorded in the image as written, not verified. Every write
    // of a row passes here: with `logAs` its outcome goes into the session log (write_audit.h)
    // under that origin; nullopt only for a WriteJob, which logs the item with its read back.
    RequestId write(int module, const dev::ParamMeta &row, const dev::RawValue &value,
                    Priority priority, std::optional<AuditOrigin> logAs, Completion done);

private:
    Session &m_session;
    const dev::DictionarySet &m_dictionaries;
    dev::HcsProduct m_product;
    mutable DeviceImage m_ownImage;
    QPointer<DeviceImage> m_image; // null: m_ownImage
};

// Cancels what is still queued of one read.
class DeviceAccess::ReadHandle
{
public:
    void cancel();
    bool finished() const { return m_finished; }

private:
    friend class DeviceAccess;
    Session *m_session = nullptr;
    std::vector<RequestId> m_ids;
    bool m_cancelled = false;
    bool m_finished = false;
};

// Rows a "read all" asks for: readable, applicable to the module's version and mode; inactive
// (x) and not-implemented (n) rows are never read.
std::vector<const dev::ParamMeta *> readableRows(const dev::Dictionary &dictionary,
                                                 const std::string &version,
                                                 const std::string &mode);

} // namespace vt::model
