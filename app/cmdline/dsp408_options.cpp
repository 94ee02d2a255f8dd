#include "dsp408_options.h"

namespace vt::cmdline {

const char kDsp408Synopsis[] =
    "ED1 image (dsp408-image, dsp408-gateway): [--out-register N] [--in-register N] "
    "[--in-function 3|4] [--register-bytes high-first|low-first] [--pzd-words "
    "high-first|low-first] [--ind-byte 2|3]";

std::optional<std::string> applyDsp408Option(const QString &name, const QString &value,
                                             dev::access::Dsp408LinkOptions &options)
{
    const std::string option = name.toStdString();
    const bool highFirst = value == QLatin1String("high-first");
    const bool lowFirst = value == QLatin1String("low-first");
    if (name == QLatin1String("--out-register") || name == QLatin1String("--in-register")) {
        bool ok = false;
        const uint n = value.toUInt(&ok, 0); // decimal or 0x…
        // The image's 7 registers must fit below 65536.
        if (!ok || n > 0xFFFFu - 7u)
            return option + " takes a register number 0..65528";
        (name == QLatin1String("--out-register") ? options.gateway.outputRegister
                                                 : options.gateway.inputRegister) =
            static_cast<std::uint16_t>(n);
        return std::nullopt;
    }
    if (name == QLatin1String("--in-function")) {
        if (value == QLatin1String("3"))
            options.gateway.inputFunction = dev::dsp408::InputFunction::HoldingRegisters;
        else if (value == QLatin1String("4"))
            options.gateway.inputFunction = dev::dsp408::InputFunction::InputRegisters;
        else
            return "--in-function takes 3 (holding registers) or 4 (input registers)";
        return std::nullopt;
    }
    if (name == QLatin1String("--register-bytes")) {
        if (!highFirst && !lowFirst)
            return "--register-bytes takes high-first or low-first";
        options.gateway.byteOrder = highFirst ? dev::dsp408::RegisterByteOrder::FirstByteHigh
                                              : dev::dsp408::RegisterByteOrder::FirstByteLow;
        return std::nullopt;
    }
    if (name == QLatin1String("--pzd-words")) {
        if (!highFirst && !lowFirst)
            return "--pzd-words takes high-first or low-first";
        options.layout.pzdWordOrder = highFirst ? dev::dsp408::WordOrder::HighWordFirst
                                                : dev::dsp408::WordOrder::LowWordFirst;
        return std::nullopt;
    }
    if (name == QLatin1String("--ind-byte")) {
        if (value != QLatin1String("2") && value != QLatin1String("3"))
            return "--ind-byte takes 2 (the manual's example) or 3";
        options.layout.indPosition = value == QLatin1String("2") ? dev::dsp408::IndPosition::Byte2
                                                                 : dev::dsp408::IndPosition::Byte3;
        return std::nullopt;
    }
    return "unknown option " + option;
}

} // namespace vt::cmdline
