// SetValuesCommand: one undo step that sets working values of one or more rows (an edit in the
// editor, a drag on the L curve, a revert, an apply from compare). Undo restores each row's old
// value; the device and file layers are never touched by undo.
#pragma once

#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <QString>
#include <QUndoCommand>
#include <functional>
#include <optional>
#include <vector>

namespace vt::model {

class ParameterDocument;

// Renders an undo step's text in the UI language of the moment ("Set C1.07 to 1,000 V").
using UndoText = std::function<QString()>;

class SetValuesCommand : public QUndoCommand
{
public:
    struct Row
    {
        int module = 0;
        const dev::ParamMeta *row = nullptr;
        std::optional<dev::RawValue> before, after;
    };
    SetValuesCommand(ParameterDocument &document, std::vector<Row> rows, UndoText text);

    // The text again, in the language switched to since the step was made.
    void retranslate();

    void undo() override;
    void redo() override;

private:
    ParameterDocument &m_document;
    std::vector<Row> m_rows;
    UndoText m_text;
};

} // namespace vt::model
