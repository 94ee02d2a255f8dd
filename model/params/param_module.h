// ParamModule: one module of a document — what the open file holds and the working value the user
// edits (what Save writes and Write sends). What the device holds is not here: it is in the
// DeviceImage, at `address`, for a module paired with the device (ParameterDocument::value with
// Layer::Device reads it). Plain value; owned by the ParameterDocument.
#pragma once

#include "dict/dictionary.h"
#include "dict/raw_value.h"
#include "files/file_rows.h"
#include "files/param_file.h"
#include "files/param_file_map.h"

#include <QString>
#include <map>
#include <optional>
#include <string>

namespace vt::model {

enum class Layer { Working, Device, File };

struct ParamModule
{
    int address = 0;
    const dev::Dictionary *dictionary = nullptr;
    std::string version;           // "51.02"; chooses the applicable rows
    std::string mode;              // HCS E00, "3"
    QString identity;              // for people: "dma-pn-v51 51.02, mode 3"
    bool identityOwn = false;      // identity is ours (a tr() sentence), not the device's own words
    dev::LocalText identityDevice; // the device's identity in both languages (identity shows one)
    QString label;                 // the user's name for the module, from the file
    bool online = false;           // paired with a module identified on the connected node
    // Paired with the device module at `address` on this or an earlier connection: the Device
    // column shows the image's values (not current after a disconnect). A file opened or a New
    // document is not paired until the device is attached again.
    bool paired = false;
    int versRaw = -1;
    std::map<const dev::ParamMeta *, dev::RawValue> file, working;
    // The module record as loaded: rows and keys this dictionary does not apply are written back
    // from here on save (nothing is dropped).
    std::optional<dev::files::ModuleRecord> record;
    std::optional<dev::files::MapReport> mapReport;

    // The file or working value (Layer::Device: ask the document).
    std::optional<dev::RawValue> value(const dev::ParamMeta *row, Layer which) const
    {
        const auto &values = which == Layer::File ? file : working;
        const auto it = values.find(row);
        return it == values.end() || which == Layer::Device
                   ? std::nullopt
                   : std::optional<dev::RawValue>(it->second);
    }
    // Rows that apply to this module's version and mode and can be accessed.
    bool active(const dev::ParamMeta &row) const
    {
        return row.access != dev::Access::Inactive && row.access != dev::Access::NotImplemented &&
               row.appliesTo(version.substr(0, version.find('.')), mode);
    }
};

// Equal raw values (numbers compared exactly: both come from the same integer or float32 grid).
inline bool sameValue(const std::optional<dev::RawValue> &a, const std::optional<dev::RawValue> &b)
{
    return a.has_value() == b.has_value() && (!a || *a == *b);
}

} // namespace vt::model
