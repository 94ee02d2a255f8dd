#include "file_rows.h"

namespace vt::dev::files {

bool isFileRow(const ParamMeta &meta)
{
    return meta.kind == RowKind::Setting;
}

} // namespace vt::dev::files
