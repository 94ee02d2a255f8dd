#include "compose_panel.h"

#include "access/node_image_adapter.h"
#include "compose_messages.h"
#include "core/hex.h"
#include "frame_detail.h"
#include "inspect/logged_frame.h"
#include "model/audit/write_audit.h"
#include "model/number_text.h"
#include "model/session/connection.h"
#include "model/text_language.h"
#include "transports/byte_span.h"
#include "widgets/actuator_confirm.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace vt::ui {
namespace {

using vt::dev::inspect::ComposeKind;

const char *const kFieldNames[] = {"tadr",     "sadr",  "unit",       "transaction", "id",
                                   "count",    "value", "modules",    "ind",         "pnu",
                                   "instance", "poll",  "deviceType", "deviceId",    "command",
                                   "data",     "node",  "index",      "subindex"};

// Which editors a kind uses ("family", "width", "tcp" are the combo / check boxes).
QStringList fieldsOf(ComposeKind kind, bool tcp)
{
    switch (kind) {
    case ComposeKind::GatewayRead: return {"tadr", "sadr", "id", "count"};
    case ComposeKind::GatewayWrite: return {"tadr", "sadr", "id", "value"};
    case ComposeKind::GatewayCyclic: return {"family", "tadr", "modules"};
    case ComposeKind::ModbusRead:
        return tcp ? QStringList{"tcp", "transaction", "unit", "id", "count"}
                   : QStringList{"tcp", "unit", "id", "count"};
    case ComposeKind::ModbusWrite:
        return tcp ? QStringList{"tcp", "transaction", "unit", "id", "value"}
                   : QStringList{"tcp", "unit", "id", "value"};
    case ComposeKind::PkwRead: return {"ind", "pnu"};
    case ComposeKind::PkwWrite: return {"ind", "pnu", "width", "value"};
    case ComposeKind::HartCommand: return {"poll", "deviceType", "deviceId", "command", "data"};
    case ComposeKind::HartParamRead:
        return {"poll", "deviceType", "deviceId", "ind", "pnu", "instance", "width"};
    case ComposeKind::HartParamWrite:
        return {"poll", "deviceType", "deviceId", "ind", "pnu", "instance", "width", "value"};
    case ComposeKind::SdoUpload: return {"node", "index", "subindex"};
    case ComposeKind::SdoDownload: return {"node", "index", "subindex", "width", "value"};
    }
    return {};
}

} // namespace

ComposePanel::ComposePanel(QWidget *parent)
    : QWidget(parent), m_kind(new QComboBox(this)), m_familyBox(new QComboBox(this)),
      m_widthBox(new QComboBox(this)), m_tcp(new QCheckBox(this)), m_form(new QFormLayout),
      m_bytes(new QLabel(this)), m_problem(new QLabel(this)), m_sendReason(new QLabel(this)),
      m_result(new QLabel(this)), m_send(new QPushButton(this)), m_detail(new FrameDetail(this))
{
    for (int k = 0; k <= static_cast<int>(ComposeKind::SdoDownload); ++k)
        m_kind->addItem(QString(), k);
    m_familyBox->addItem(QStringLiteral("DMA"), static_cast<int>(vt::dev::hcs::Family::Dma));
    m_familyBox->addItem(QStringLiteral("OPAT"), static_cast<int>(vt::dev::hcs::Family::Opat));
    for (int w : {1, 2, 4})
        m_widthBox->addItem(QString(), w);
    m_widthBox->setCurrentIndex(1);

    auto addRow = [this](const QString &name, QWidget *editor) {
        auto *label = new QLabel(this);
        m_labels[name] = label;
        m_form->addRow(label, editor);
    };
    addRow(QStringLiteral("kind"), m_kind);
    addRow(QStringLiteral("family"), m_familyBox);
    addRow(QStringLiteral("tcp"), m_tcp);
    for (const char *name : kFieldNames) {
        auto *edit = new QLineEdit(this);
        edit->setObjectName(QString::fromLatin1(name));
        m_edits[QString::fromLatin1(name)] = edit;
        addRow(QString::fromLatin1(name), edit);
        connect(edit, &QLineEdit::textChanged, this, &ComposePanel::rebuild);
    }
    addRow(QStringLiteral("width"), m_widthBox);
    // Defaults: the manuals' worked examples (OPAT manual §2.7: TADR 0x23; §4.6.1 IND 3).
    const std::pair<const char *, const char *> defaults[] = {
        {"tadr", "0x23"}, {"sadr", "0"},  {"unit", "1"},       {"transaction", "1"},
        {"id", "0x0007"}, {"count", "1"}, {"value", "0"},      {"modules", "0, 1000, 0"},
        {"ind", "3"},     {"pnu", "73"},  {"instance", "0"},   {"poll", "0"},
        {"command", "0"}, {"node", "1"},  {"index", "0x2007"}, {"subindex", "0"}};
    for (const auto &[name, text] : defaults)
        m_edits[QString::fromLatin1(name)]->setText(QString::fromLatin1(text));

    m_bytes->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_bytes->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    for (QLabel *l : {m_problem, m_sendReason})
        l->setStyleSheet(QStringLiteral("color: #c81e1e;"));
    m_problem->setWordWrap(true);
    m_sendReason->setWordWrap(true);
    m_result->setWordWrap(true);

    auto *sendRow = new QHBoxLayout;
    sendRow->addWidget(m_send);
    sendRow->addWidget(m_sendReason, 1);
    auto *left = new QVBoxLayout;
    left->addLayout(m_form);
    left->addWidget(m_problem);
    left->addWidget(m_bytes);
    left->addLayout(sendRow);
    left->addWidget(m_result);
    left->addStretch(1);
    auto *layout = new QHBoxLayout(this);
    layout->addLayout(left);
    layout->addWidget(m_detail, 1);

    connect(m_kind, &QComboBox::currentIndexChanged, this, &ComposePanel::rebuild);
    connect(m_familyBox, &QComboBox::currentIndexChanged, this, &ComposePanel::rebuild);
    connect(m_widthBox, &QComboBox::currentIndexChanged, this, &ComposePanel::rebuild);
    connect(m_tcp, &QCheckBox::toggled, this, &ComposePanel::rebuild);
    connect(m_send, &QPushButton::clicked, this, &ComposePanel::send);
    retranslate();
}

void ComposePanel::setConnection(vt::model::Connection *connection,
                                 const std::vector<vt::model::ModuleInfo> &modules)
{
    m_connection = connection;
    m_modules = modules;
    if (connection) {
        // Pre-fill the addresses the link talks to, so the first frame goes somewhere real.
        const auto addresses = connection->moduleAddresses();
        if (!addresses.empty()) {
            const QString first = QString::number(addresses.front());
            for (const char *name : {"sadr", "unit", "poll", "node"})
                m_edits[QString::fromLatin1(name)]->setText(first);
        }
        const vt::dev::LinkProtocol protocol = connection->protocol();
        if (protocol == vt::dev::LinkProtocol::ModbusTcp)
            setModbusTcp(true);
        else if (protocol == vt::dev::LinkProtocol::ModbusRtu)
            setModbusTcp(false);
        // The frame offered first is one this link carries.
        if (const auto read = readKindFor(protocol);
            read && (!m_frame || m_frame->link != protocol))
            setKind(*read);
    }
    updateSend();
}

void ComposePanel::clearConnection()
{
    m_connection = nullptr;
    m_modules.clear();
    updateSend();
}

void ComposePanel::setConfirmation(std::function<bool(const QString &)> confirm)
{
    m_confirm = std::move(confirm);
}

void ComposePanel::setKind(ComposeKind kind)
{
    m_kind->setCurrentIndex(m_kind->findData(static_cast<int>(kind)));
}

ComposeKind ComposePanel::kind() const
{
    return static_cast<ComposeKind>(m_kind->currentData().toInt());
}

void ComposePanel::setFieldText(const QString &name, const QString &text)
{
    const auto it = m_edits.find(name);
    if (it != m_edits.end())
        it->second->setText(text);
}

void ComposePanel::setModbusTcp(bool tcp)
{
    m_tcp->setChecked(tcp);
}

void ComposePanel::setWidth(int bytes)
{
    const int i = m_widthBox->findData(bytes);
    if (i >= 0)
        m_widthBox->setCurrentIndex(i);
}

void ComposePanel::setFamily(vt::dev::hcs::Family family)
{
    m_familyBox->setCurrentIndex(m_familyBox->findData(static_cast<int>(family)));
}

QString ComposePanel::problem() const
{
    return m_problemText;
}

std::optional<long long> ComposePanel::number(const QString &name, QString *problem) const
{
    const QString text = m_edits.at(name)->text().trimmed();
    bool ok = false;
    long long v = 0;
    if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ||
        text.startsWith(QLatin1String("-0x"), Qt::CaseInsensitive)) {
        const bool negative = text.startsWith(QLatin1Char('-'));
        v = text.mid(negative ? 3 : 2).toLongLong(&ok, 16);
        if (negative)
            v = -v;
    } else {
        // Decimal fields are whole numbers in the UI language's notation, refused otherwise.
        model::NumberRules rules;
        rules.minimum = -9.0e15; // exact in a double; far beyond any telegram field
        rules.maximum = 9.0e15;
        const model::NumberParse parsed = model::parseNumber(text, model::textLanguage(), rules);
        if (!parsed.ok()) {
            if (problem && problem->isEmpty())
                *problem = tr("%1: %2").arg(labelText(name), parsed.refusal);
            return std::nullopt;
        }
        return static_cast<long long>(*parsed.value);
    }
    if (!ok && problem && problem->isEmpty())
        *problem = tr("%1: not a number").arg(labelText(name));
    return ok ? std::optional<long long>(v) : std::nullopt;
}

QString ComposePanel::labelText(const QString &name) const
{
    const auto label = m_labels.find(name);
    return label == m_labels.end() ? QString() : label->second->text().remove(QLatin1Char(':'));
}

void ComposePanel::rebuild()
{
    updateVisibility();
    vt::dev::inspect::ComposeSpec s;
    s.kind = kind();
    s.family = static_cast<vt::dev::hcs::Family>(m_familyBox->currentData().toInt());
    s.width = m_widthBox->currentData().toInt();
    s.modbusTcp = m_tcp->isChecked();
    QString problem;
    const QStringList used = fieldsOf(s.kind, s.modbusTcp);
    auto take = [&](const char *name, long long &target) {
        if (!used.contains(QLatin1String(name)))
            return;
        if (const auto v = number(QString::fromLatin1(name), &problem))
            target = *v;
    };
    take("tadr", s.tadr);
    take("sadr", s.sadr);
    take("unit", s.unit);
    take("transaction", s.transaction);
    take("id", s.id);
    take("count", s.count);
    take("value", s.value);
    take("ind", s.ind);
    take("pnu", s.pnu);
    take("instance", s.instance);
    take("poll", s.pollAddress);
    take("command", s.hartCommand);
    take("node", s.node);
    take("index", s.index);
    take("subindex", s.subindex);
    if (used.contains(QLatin1String("deviceType")) &&
        !m_edits[QStringLiteral("deviceType")]->text().trimmed().isEmpty()) {
        long long type = 0, id = 0;
        take("deviceType", type);
        take("deviceId", id);
        if (type < 0 || type > 0xFFFF || id < 0 || id > 0xFFFFFF) {
            if (problem.isEmpty())
                problem = tr("Long address: device type 0..0xFFFF, device id 0..0xFFFFFF");
        } else {
            s.hartDeviceType = static_cast<std::uint16_t>(type);
            s.hartDeviceId = static_cast<std::uint32_t>(id);
        }
    }
    if (used.contains(QLatin1String("data"))) {
        const auto hex = vt::dev::parseHex(m_edits[QStringLiteral("data")]->text().toStdString());
        if (hex)
            s.hartData = *hex;
        else if (problem.isEmpty())
            problem = tr("Data: not hex");
    }
    if (used.contains(QLatin1String("modules"))) {
        // "CTRL,VALUE1,VALUE2" per module, modules separated by ';' (OPAT manual §3.1).
        const QStringList modules =
            m_edits[QStringLiteral("modules")]->text().split(QLatin1Char(';'), Qt::SkipEmptyParts);
        for (const QString &m : modules) {
            const QStringList parts = m.split(QLatin1Char(','));
            bool ok = parts.size() == 3;
            long long v[3] = {0, 0, 0};
            for (int i = 0; ok && i < 3; ++i) {
                const QString t = parts[i].trimmed();
                v[i] = t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                           ? t.mid(2).toLongLong(&ok, 16)
                           : t.toLongLong(&ok);
            }
            ok = ok && v[0] >= 0 && v[0] <= 255 && v[1] >= -32768 && v[1] <= 32767 &&
                 v[2] >= -32768 && v[2] <= 32767;
            if (!ok) {
                if (problem.isEmpty())
                    problem = tr("Modules: \"CTRL,VALUE1,VALUE2\" per module (0..255, two "
                                 "-32768..32767), separated by \";\"");
                break;
            }
            s.modules.push_back({static_cast<std::uint8_t>(v[0]), static_cast<std::int16_t>(v[1]),
                                 static_cast<std::int16_t>(v[2])});
        }
    }
    m_spec = s;
    m_frame.reset();
    if (problem.isEmpty()) {
        auto composed = vt::dev::inspect::compose(s);
        if (composed)
            m_frame = std::move(*composed);
        else
            problem = composeRefusalText(composed.error(),
                                         [this](const QString &key) { return labelText(key); });
    }
    m_problemText = problem;
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    if (m_frame) {
        m_bytes->setText(QString::fromStdString(vt::dev::toHex(m_frame->bytes)));
        vt::dev::AnyOptions o;
        o.family = s.family;
        o.direction = vt::dev::Direction::Request;
        o.cobId = m_frame->cobId;
        o.protocol = m_frame->protocol;
        const auto d = vt::dev::describeAny(m_frame->bytes, o);
        if (d)
            m_detail->setFrame(vt::link::toByteArray(m_frame->bytes), *d);
        else
            m_detail->setUndescribed(vt::link::toByteArray(m_frame->bytes),
                                     QString::fromStdString(d.error()));
    } else {
        m_bytes->clear();
        m_detail->clear();
    }
    updateSend();
}

void ComposePanel::updateVisibility()
{
    const QStringList used = fieldsOf(kind(), m_tcp->isChecked());
    for (const auto &[name, label] : m_labels) {
        if (name == QLatin1String("kind"))
            continue;
        const bool show = used.contains(name);
        label->setVisible(show);
    }
    m_familyBox->setVisible(used.contains(QLatin1String("family")));
    m_tcp->setVisible(used.contains(QLatin1String("tcp")));
    m_widthBox->setVisible(used.contains(QLatin1String("width")));
    for (const auto &[name, edit] : m_edits)
        edit->setVisible(used.contains(name));
}

QString ComposePanel::sendBlockedReason() const
{
    if (!m_frame)
        return tr("Nothing to send: the fields do not make a frame.");
    if (!m_connection || !m_connection->isOpen())
        return tr("Not connected.");
    if (m_busy)
        return tr("Waiting for the answer to the last frame.");
    if (!m_frame->link)
        return tr("No link of ValveTune carries %1 frames (PROFIBUS DP needs a master card); copy "
                  "the bytes instead.")
            .arg(QString::fromLatin1(vt::dev::key(m_frame->protocol)));
    if (m_connection->protocol() != *m_frame->link)
        return tr("The current link speaks %1; this frame needs %2.")
            .arg(m_connection->protocolKey(), QString::fromLatin1(vt::dev::key(*m_frame->link)));
    return {};
}

bool ComposePanel::canSend() const
{
    return sendBlockedReason().isEmpty();
}

void ComposePanel::updateSend()
{
    const QString reason = sendBlockedReason();
    m_send->setEnabled(reason.isEmpty());
    m_send->setToolTip(reason);
    m_sendReason->setText(m_frame ? reason : QString());
}

int ComposePanel::moduleOf(const vt::dev::inspect::ComposeSpec &s) const
{
    switch (s.kind) {
    case ComposeKind::GatewayRead:
    case ComposeKind::GatewayWrite: return static_cast<int>(s.sadr);
    case ComposeKind::GatewayCyclic: return 0;
    case ComposeKind::ModbusRead:
    case ComposeKind::ModbusWrite: return static_cast<int>(s.unit);
    case ComposeKind::PkwRead:
    case ComposeKind::PkwWrite: return -1;
    case ComposeKind::HartCommand:
    case ComposeKind::HartParamRead:
    case ComposeKind::HartParamWrite:
        return s.hartDeviceType ? -1 : static_cast<int>(s.pollAddress);
    case ComposeKind::SdoUpload:
    case ComposeKind::SdoDownload: return static_cast<int>(s.node);
    }
    return -1;
}

bool ComposePanel::send()
{
    if (!canSend())
        return false;
    const vt::dev::inspect::ComposedFrame frame = *m_frame;
    const int module = moduleOf(m_spec);
    const vt::dev::ParamMeta *row = frame.writes ? writtenRow(m_spec) : nullptr;
    if (frame.writes) {
        const QString hex = QString::fromStdString(vt::dev::toHex(frame.bytes));
        const QString question =
            row ? tr("This frame changes the device:\n%1\n%2\n\nSend it?")
                      .arg(actuatorWriteLine(module, *row,
                                             m_connection->access().image().value(module, row),
                                             vt::dev::RawValue{static_cast<double>(m_spec.value)},
                                             vt::model::textLanguage()),
                           hex)
                : tr("This frame changes the device:\n%1\n\nSend it?").arg(hex);
        const bool yes = m_confirm ? m_confirm(question)
                                   : QMessageBox::question(this, tr("Send a write"), question) ==
                                         QMessageBox::Yes;
        if (!yes || !canSend())
            return false;
    }
    std::size_t image = 0;
    if (const auto *node = dynamic_cast<const vt::dev::access::NodeImageAdapter *>(
            &m_connection->session().adapter()))
        image = node->layout().outputBytes;
    auto t = vt::dev::access::Transaction::rawFrame(moduleOf(m_spec),
                                                    vt::dev::inspect::wireBytes(frame, image));
    m_busy = true;
    updateSend();
    m_resultText = [] { return tr("Sent; waiting for the answer…"); };
    m_result->setText(m_resultText());
    QPointer<ComposePanel> self(this);
    const bool writes = frame.writes;
    const QString frameHex = QString::fromStdString(vt::dev::toHex(t.raw));
    m_connection->session().submit(
        std::move(t), vt::model::Priority::User,
        [self, writes, module, row, spec = m_spec,
         before = row ? m_connection->access().image().value(module, row) : std::nullopt,
         value = m_spec.value, frameHex](const vt::model::Outcome &o) {
            // A frame that writes goes into the session log whatever became of the panel.
            if (writes)
                vt::model::auditExchange(module, row, before,
                                         vt::dev::RawValue{static_cast<double>(value)}, o,
                                         vt::model::AuditOrigin::Compose, frameHex);
            if (!self)
                return;
            self->m_busy = false;
            // The answer decoded, as the telegram list decodes it; the text is rendered again
            // when the language changes while it shows.
            const auto decoded = self->m_connection
                                     ? decodeAnswer(o, self->m_connection->protocol(), spec,
                                                    self->dictionaryOf(module))
                                     : std::nullopt;
            if (decoded)
                self->m_detail->setFrame(vt::link::toByteArray(o.reply.frame), *decoded);
            self->m_resultText = answerText(o, decoded);
            // A write may have changed the device whatever the answer: read that parameter back
            // so the device image follows; an address no dictionary names cannot be followed.
            if (writes && o.sent && self->m_connection) {
                if (row) {
                    self->m_connection->access().read(module, {row}, vt::model::Priority::User,
                                                      [](const vt::model::ReadResult &) {});
                } else {
                    self->m_resultText = [first = self->m_resultText] {
                        return first() + QLatin1Char('\n') +
                               tr("No parameter of the module's dictionary has this address: the "
                                  "editor's Device column cannot follow it. Read the device "
                                  "again.");
                    };
                }
            }
            const QString text = self->m_resultText();
            self->m_result->setText(text);
            self->updateSend();
            emit self->sendFinished(text, o.status == vt::model::OutcomeStatus::Ok);
            if (writes && row && o.status == vt::model::OutcomeStatus::Ok) {
                vt::model::WriteItem item;
                item.row = row;
                item.value = vt::dev::RawValue{static_cast<double>(value)};
                item.before = before;
                item.status = vt::model::WriteStatus::Written;
                emit self->wrote(module, {item});
            }
        });
    return true;
}

const vt::dev::Dictionary *ComposePanel::dictionaryOf(int address) const
{
    for (const vt::model::ModuleInfo &info : m_modules)
        if (info.address == address)
            return info.dictionary;
    return nullptr;
}

const vt::dev::ParamMeta *ComposePanel::writtenRow(const vt::dev::inspect::ComposeSpec &spec) const
{
    return rowWrittenBy(dictionaryOf(moduleOf(spec)), spec);
}

void ComposePanel::retranslate()
{
    if (m_resultText)
        m_result->setText(m_resultText());
    const QString kinds[] = {tr("HCS CMD 3 read"),
                             tr("HCS CMD 6 write"),
                             tr("HCS CMD 15 cyclic"),
                             tr("Modbus FC 3 read"),
                             tr("Modbus FC 6 write"),
                             tr("PKW read"),
                             tr("PKW write"),
                             tr("HART command"),
                             tr("HART parameter read (128/130/132)"),
                             tr("HART parameter write (129/131/133)"),
                             tr("SDO upload (read)"),
                             tr("SDO download (write)")};
    for (int i = 0; i < m_kind->count(); ++i)
        m_kind->setItemText(i, kinds[i]);
    m_widthBox->setItemText(0, tr("1 byte"));
    m_widthBox->setItemText(1, tr("2 bytes"));
    m_widthBox->setItemText(2, tr("4 bytes"));
    m_tcp->setText(tr("Modbus TCP (MBAP header)"));
    const std::pair<const char *, QString> labels[] = {
        {"kind", tr("Frame:")},
        {"family", tr("Family:")},
        {"tcp", tr("Framing:")},
        {"tadr", tr("TADR:")},
        {"sadr", tr("SADR (module):")},
        {"unit", tr("Unit id:")},
        {"transaction", tr("Transaction id:")},
        {"id", tr("Parameter ID / register:")},
        {"count", tr("Count:")},
        {"value", tr("Value (raw):")},
        {"modules", tr("Modules (CTRL,V1,V2; …):")},
        {"ind", tr("IND:")},
        {"pnu", tr("PNU:")},
        {"instance", tr("Instance:")},
        {"poll", tr("Poll address:")},
        {"deviceType", tr("Device type (long frame):")},
        {"deviceId", tr("Device id (long frame):")},
        {"command", tr("Command:")},
        {"data", tr("Data (hex):")},
        {"node", tr("Node id:")},
        {"index", tr("Object index:")},
        {"subindex", tr("Sub-index:")},
        {"width", tr("Width:")}};
    for (const auto &[name, text] : labels)
        m_labels.at(QString::fromLatin1(name))->setText(text);
    m_send->setText(tr("Send"));
    rebuild();
}

void ComposePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace vt::ui
