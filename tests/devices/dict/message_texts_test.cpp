// Every device message of the protocol core exists in both
// languages. Walks each table through its public lookup over the whole input range (so the
// "unknown …" / "reserved" fall-backs are checked too): HCS exception codes and error numbers,
// CMD 15 control and status bits, Modbus exception names, DSP-408 AK / error codes / states /
// transitions / control and status bits, HART commands / response codes / status bits,
// PROFIdrive STW1/ZSW1 bits, CANopen abort codes, decode errors and access texts.
#include "canopen/sdo.h"
#include "core/decode_error.h"
#include "dict/param_meta.h"
#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "dsp408/state_machine.h"
#include "hart/texts.h"
#include "hcs/exceptions.h"
#include "hcs/profiles.h"
#include "hcs/status_bits.h"
#include "modbus/exceptions.h"
#include "profidrive/stw1_zsw1.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace vt::dev;

namespace {

// Collects "table key" for every text that lacks English or German.
class Audit
{
public:
    void check(const LocalText &text, const std::string &where)
    {
        ++m_checked;
        if (text.en.empty() || text.de.empty())
            m_missing.push_back(where + " (en '" + text.en + "', de '" + text.de + "')");
    }
    void check(const std::optional<LocalText> &text, const std::string &where)
    {
        if (text)
            check(*text, where);
    }
    int checked() const { return m_checked; }
    std::string report() const
    {
        std::string out;
        for (const std::string &m : m_missing)
            out += m + "\n";
        return out;
    }
    bool complete() const { return m_missing.empty(); }

private:
    int m_checked = 0;
    std::vector<std::string> m_missing;
};

std::string n(int value)
{
    return std::to_string(value);
}

} // namespace

TEST(GermanMessages, AuditReportsATextWithoutGerman)
{
    Audit audit;
    audit.check(LocalText{"complete", "vollständig"}, "good");
    EXPECT_TRUE(audit.complete());
    audit.check(LocalText{"English only", ""}, "bad");
    audit.check(std::optional<LocalText>{}, "absent entries are not texts");
    EXPECT_FALSE(audit.complete());
    EXPECT_EQ(audit.report(), "bad (en 'English only', de '')\n");
    EXPECT_EQ(audit.checked(), 2);
}

TEST(GermanMessages, HcsExceptionCodesAndErrorNumbers)
{
    Audit audit;
    int listed = 0;
    for (hcs::Family family : {hcs::Family::Opat, hcs::Family::Dma}) {
        const std::string f(hcs::familyName(family));
        for (std::uint8_t cmd : {hcs::kCmdRead, hcs::kCmdWrite, hcs::kCmdCyclic}) {
            for (int code = 0; code < 256; ++code) {
                const auto c = static_cast<std::uint8_t>(code);
                const std::string where = f + " CMD " + n(cmd) + " EXCE " + n(code);
                listed += hcs::exceptionText(family, cmd, c).has_value();
                audit.check(hcs::exceptionText(family, cmd, c), where);
                audit.check(hcs::exceptionTextOrUnknown(family, cmd, c), where + " or unknown");
                audit.check(modbus::exceptionText(cmd, c, family),
                            "Modbus FC " + n(cmd) + " " + where);
            }
        }
        for (int number = 0; number < 256; ++number)
            audit.check(hcs::errorNumberText(family, static_cast<std::uint8_t>(number)),
                        f + " error number " + n(number));
    }
    for (int code = 0; code < 256; ++code)
        audit.check(modbus::exceptionName(static_cast<std::uint8_t>(code)),
                    "Modbus exception " + n(code));
    EXPECT_EQ(listed, 3 * 12 + 6 + 6 + 9); // OPAT: 12 codes per command; DMA: 6, 6, 9
    EXPECT_TRUE(audit.complete()) << audit.report();
}

TEST(GermanMessages, HcsControlAndStatusBitsOfEveryProfile)
{
    Audit audit;
    for (const hcs::ProfileInfo &info : hcs::allProfiles()) {
        const std::string p(info.key);
        audit.check(info.title, p + " title");
        for (const hcs::ValueMeaning *v :
             {&info.request1, &info.request2, &info.response1, &info.response2})
            audit.check(v->text, p + " " + std::string(v->parameter));
        for (const auto &bits :
             {hcs::controlBits(info.profile), hcs::statusHighBits(info.profile),
              hcs::statusLowBits(info.profile), hcs::statusLowBits(info.profile, true)})
            for (const hcs::BitMeaning &b : bits)
                audit.check(b.text, p + " " + std::string(b.name));
    }
    EXPECT_TRUE(audit.complete()) << audit.report();
}

TEST(GermanMessages, Dsp408Texts)
{
    Audit audit;
    for (int ak = 0; ak < 16; ++ak) {
        audit.check(dsp408::requestIdText(static_cast<std::uint8_t>(ak)), "request AK " + n(ak));
        audit.check(dsp408::responseIdText(static_cast<std::uint8_t>(ak)), "response AK " + n(ak));
    }
    for (int code = 0; code < 65536; ++code)
        audit.check(dsp408::pkwErrorText(static_cast<std::uint16_t>(code)), "PKW error " + n(code));
    for (int bit = 0; bit < 16; ++bit) {
        audit.check(dsp408::controlBitText(bit), "control bit " + n(bit));
        audit.check(dsp408::statusBitText(bit), "status bit " + n(bit));
    }
    for (int s = 0; s <= static_cast<int>(dsp408::State::Fault); ++s)
        audit.check(dsp408::stateText(static_cast<dsp408::State>(s)),
                    dsp408::stateName(static_cast<dsp408::State>(s)));
    for (int t = 0; t <= static_cast<int>(dsp408::Transition::Tr567); ++t)
        audit.check(dsp408::transitionText(static_cast<dsp408::Transition>(t)),
                    dsp408::transitionName(static_cast<dsp408::Transition>(t)));
    EXPECT_TRUE(audit.complete()) << audit.report();
}

TEST(GermanMessages, HartTexts)
{
    Audit audit;
    for (int code = 0; code < 256; ++code) {
        audit.check(hart::commandText(static_cast<std::uint8_t>(code)), "command " + n(code));
        audit.check(hart::responseCodeText(static_cast<std::uint8_t>(code)),
                    "response code " + n(code));
    }
    for (int bit = 0; bit < 8; ++bit) {
        audit.check(hart::commErrorBitText(bit), "communication error bit " + n(bit));
        audit.check(hart::deviceStatusBitText(bit), "device status bit " + n(bit));
    }
    EXPECT_TRUE(audit.complete()) << audit.report();
}

TEST(GermanMessages, ProfidriveWordBits)
{
    Audit audit;
    for (const auto &[word, bits] :
         {std::pair{"STW1", profidrive::stw1Bits()}, std::pair{"ZSW1", profidrive::zsw1Bits()}}) {
        EXPECT_EQ(bits.size(), 16u);
        for (const profidrive::WordBit &b : bits) {
            const std::string where = std::string(word) + " " + std::string(b.name);
            audit.check(b.whenSet, where + " set");
            if (!b.whenClear.en.empty() || !b.whenClear.de.empty())
                audit.check(b.whenClear, where + " clear");
        }
    }
    EXPECT_TRUE(audit.complete()) << audit.report();
}

TEST(GermanMessages, CanopenAbortCodes)
{
    Audit audit;
    const std::vector<std::uint32_t> codes = canopen::knownAbortCodes();
    EXPECT_GE(codes.size(), 30u);
    for (std::uint32_t code : codes) {
        EXPECT_TRUE(canopen::isKnownAbortCode(code));
        audit.check(canopen::abortCodeText(code), "abort code " + std::to_string(code));
    }
    audit.check(canopen::abortCodeText(0x12345678), "unknown abort code");
    EXPECT_TRUE(audit.complete()) << audit.report();
}

TEST(GermanMessages, DecodeErrorsAndAccessTexts)
{
    Audit audit;
    for (int c = 0; c <= static_cast<int>(DecodeErrc::DeviceException); ++c) {
        audit.check(errcText(static_cast<DecodeErrc>(c)), "decode error " + n(c));
        audit.check(describeError(DecodeError{static_cast<DecodeErrc>(c), 3, 2, "detail"}),
                    "described decode error " + n(c));
    }
    for (int a = 0; a <= static_cast<int>(Access::NotImplemented); ++a)
        audit.check(accessText(static_cast<Access>(a)), "access " + n(a));
    EXPECT_TRUE(audit.complete()) << audit.report();
}
