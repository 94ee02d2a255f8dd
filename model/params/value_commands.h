// SetValuesCommand: one undo step that sets working values of one or more rows (an edit in the
// editor, a drag on the L curve, a revert, an apply from compare). Undo restores each row's old
// value; the device and file layers are never touched by undo.
#pragma once

#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <QUndoCommand>
#include <optional>
#include <vector>

namespace vt::model {

class ParameterDocument;

class SetValuesCommand : public QUndoCommand
{
public:
    struct Row
    {
        int module = 0;
        const dev::ParamMeta *row = nullptr;
        std::optional<dev::RawValue> before, after;
    };
    SetValuesCommand(ParameterDocument &document, std::vector<Row> rows, const QString &text);

    void undo() override;
    void redo() override;

private:
    ParameterDocument &m_document;
    std::vector<Row> m_rows;
};

} // namespace vt::model
