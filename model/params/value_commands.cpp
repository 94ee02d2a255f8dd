#include "value_commands.h"

#include "parameter_document.h"

namespace vt::model {

SetValuesCommand::SetValuesCommand(ParameterDocument &document, std::vector<Row> rows,
                                   UndoText text)
    : QUndoCommand(text ? text() : QString()), m_document(document), m_rows(std::move(rows)),
      m_text(std::move(text))
{
}

void SetValuesCommand::retranslate()
{
    if (m_text)
        setText(m_text());
}

void SetValuesCommand::undo()
{
    for (auto it = m_rows.rbegin(); it != m_rows.rend(); ++it)
        m_document.setWorking(it->module, it->row, it->before);
}

void SetValuesCommand::redo()
{
    for (const Row &r : m_rows)
        m_document.setWorking(r.module, r.row, r.after);
}

} // namespace vt::model
