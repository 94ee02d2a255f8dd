// CurveBinding: keeps the linearisation curve editor's model (LCurveTableModel) and one module
// of the ParameterDocument in step — document values (read, file, undo) go into the curves, and
// each completed curve edit (a drag, a table entry) becomes one undoable document edit.
#pragma once

#include "dict/param_meta.h"

#include <QObject>
#include <optional>

namespace vt::model {

class LCurveTableModel;
class ParameterDocument;

class CurveBinding : public QObject
{
    Q_OBJECT
public:
    CurveBinding(ParameterDocument &document, LCurveTableModel &curves, QObject *parent = nullptr);

    // The module whose L block is shown; -1 for none. Modules without curves show none.
    void setModule(int module);
    int module() const { return m_module; }

signals:
    // The module shown now (its address); -1: none.
    void moduleShown(int address);

private:
    void reload();
    std::optional<double> displayOf(const dev::ParamMeta &row) const;

    ParameterDocument &m_document;
    LCurveTableModel &m_curves;
    int m_module = -1;
};

} // namespace vt::model
