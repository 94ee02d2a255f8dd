#include "param_meta.h"

#include "core/key_lookup.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>

namespace vt::dev {

const char *key(RowKind kind)
{
    switch (kind) {
    case RowKind::Setting: return "setting";
    case RowKind::Process: return "process";
    case RowKind::Live: return "live";
    }
    return "?";
}

template<> std::optional<RowKind> fromKey<RowKind>(std::string_view text)
{
    return keyLookup<RowKind>(kRowKinds, text);
}

const EnumLabel *ParamMeta::findEnum(std::int64_t value) const
{
    const auto it = std::find_if(enums.begin(), enums.end(),
                                 [&](const EnumLabel &e) { return e.value == value; });
    return it == enums.end() ? nullptr : &*it;
}

bool ParamMeta::appliesTo(const std::string &version, const std::string &mode) const
{
    const auto has = [](const std::vector<std::string> &list, const std::string &v) {
        return list.empty() || v.empty() || std::find(list.begin(), list.end(), v) != list.end();
    };
    return has(versions, version) && has(modes, mode);
}

std::string ParamMeta::addressText() const
{
    char buf[64];
    if (id) {
        std::snprintf(buf, sizeof buf, "ID 0x%02X", static_cast<unsigned>(*id));
    } else if (ind && pnu) {
        if (instance != 0)
            std::snprintf(buf, sizeof buf, "IND %d / PNU %d / inst %d", *ind, *pnu, instance);
        else
            std::snprintf(buf, sizeof buf, "IND %d / PNU %d", *ind, *pnu);
    } else {
        return {};
    }
    return buf;
}

double typeMin(RawType type)
{
    switch (type) {
    case RawType::Int8: return -128;
    case RawType::Int16: return -32768;
    case RawType::Int32: return -2147483648.0;
    case RawType::Float32: return -FLT_MAX;
    case RawType::UInt8:
    case RawType::UInt16:
    case RawType::UInt32:
    case RawType::String: return 0;
    }
    return 0;
}

std::size_t wireBytes(RawType type)
{
    switch (type) {
    case RawType::Int8:
    case RawType::UInt8: return 1;
    case RawType::Int16:
    case RawType::UInt16: return 2;
    case RawType::Int32:
    case RawType::UInt32:
    case RawType::Float32: return 4;
    case RawType::String: break;
    }
    return 0;
}

double typeMax(RawType type)
{
    switch (type) {
    case RawType::Int8: return 127;
    case RawType::UInt8: return 255;
    case RawType::Int16: return 32767;
    case RawType::UInt16: return 65535;
    case RawType::Int32: return 2147483647.0;
    case RawType::UInt32: return 4294967295.0;
    case RawType::Float32: return FLT_MAX;
    case RawType::String: return 0;
    }
    return 0;
}

const char *accessKey(Access access)
{
    switch (access) {
    case Access::Read: return "r";
    case Access::ReadWrite: return "rw";
    case Access::Write: return "w";
    case Access::Inactive: return "x";
    case Access::NotImplemented: return "n";
    }
    return "r";
}

const char *rawTypeKey(RawType type)
{
    switch (type) {
    case RawType::Int8: return "int8";
    case RawType::UInt8: return "uint8";
    case RawType::Int16: return "int16";
    case RawType::UInt16: return "uint16";
    case RawType::Int32: return "int32";
    case RawType::UInt32: return "uint32";
    case RawType::Float32: return "float32";
    case RawType::String: return "string";
    }
    return "int16";
}

std::optional<Access> parseAccess(const std::string &key)
{
    for (Access a :
         {Access::Read, Access::ReadWrite, Access::Write, Access::Inactive, Access::NotImplemented})
        if (key == accessKey(a))
            return a;
    return std::nullopt;
}

std::optional<RawType> parseRawType(const std::string &key)
{
    for (RawType t : {RawType::Int8, RawType::UInt8, RawType::Int16, RawType::UInt16,
                      RawType::Int32, RawType::UInt32, RawType::Float32, RawType::String})
        if (key == rawTypeKey(t))
            return t;
    return std::nullopt;
}

LocalText accessText(Access access)
{
    switch (access) {
    case Access::Read: return {"read only", "nur lesen"};
    case Access::ReadWrite: return {"read/write", "lesen/schreiben"};
    case Access::Write: return {"write only", "nur schreiben"};
    case Access::Inactive: return {"implemented, not active", "implementiert, nicht aktiv"};
    case Access::NotImplemented: return {"not yet implemented", "noch nicht implementiert"};
    }
    return {};
}

} // namespace vt::dev
