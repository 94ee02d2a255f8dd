// Item roles through which the parameter models expose metadata to delegates and views
// (STYLE.md rule 11: models expose metadata through roles, delegates read it).
#pragma once

#include <Qt>

namespace vt::model {

enum ParamRole {
    MetaRole = Qt::UserRole + 1, // const dev::ParamMeta * as quintptr (0 on module/block rows)
    ModuleIndexRole,             // index of the module in the document
    RawValueRole,                // working raw value: double or QString
    DisplayMinRole,              // double, display units (numbers only)
    DisplayMaxRole,
    DecimalsRole,   // int
    UnitRole,       // QString
    EnumLabelsRole, // QVariantList of QVariantMap{value, text}
    BitLabelsRole,  // QVariantList of QVariantMap{bit, text} (bit-field rows)
    ReadOnlyRole,   // bool: not writable (no editor; greyed unless live)
    InactiveRole,   // bool: x / n rows, or not for this version/mode
    ChangedRole,    // bool: working value differs from the file (or, without one, the first read)
    DiffersFromDeviceRole, // bool: working value differs from the device's last known value
    HelpRole,              // QString: description, address, range, access for the help pane
    SearchTextRole,        // QString: name, label and description for the search box
    NodeKindRole,          // int: NodeKind
    LiveRole,              // bool: a live value (status the module updates; the delegate marks it)
};

enum class NodeKind { Module = 1, Block = 2, Branch = 3, Parameter = 4 };

} // namespace vt::model
