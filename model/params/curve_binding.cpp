#include "curve_binding.h"

#include "core/version.h"
#include "dict/cooking.h"
#include "model/curve/lcurve_table_model.h"
#include "parameter_document.h"

#include <cmath>

namespace vt::model {

CurveBinding::CurveBinding(ParameterDocument &document, LCurveTableModel &curves, QObject *parent)
    : QObject(parent), m_document(document), m_curves(curves)
{
    connect(&m_document, &ParameterDocument::modulesReset, this, [this] {
        // Until a module is chosen the page shows the first, as the monitor does: its curve, or
        // that it has none.
        if (m_module < 0 || m_module >= m_document.moduleCount())
            m_module = m_document.moduleCount() > 0 ? 0 : -1;
        reload();
    });
    connect(&m_document, &ParameterDocument::moduleValuesChanged, this, [this](int module) {
        if (module == m_module)
            m_curves.setValues([this](const dev::ParamMeta &row) { return displayOf(row); });
    });
    connect(&m_document, &ParameterDocument::valueChanged, this,
            [this](int module, const dev::ParamMeta *row) {
                if (module != m_module || !row || row->block != "L")
                    return;
                m_curves.setRowValue(row, displayOf(*row));
            });
    connect(&m_curves, &LCurveTableModel::rowsEdited, this,
            [this](const QList<LCurveRowEdit> &edits) {
                std::vector<std::pair<const dev::ParamMeta *, double>> values;
                for (const LCurveRowEdit &e : edits) {
                    const double factor = e.row->scale.factor != 0 ? e.row->scale.factor : 1.0;
                    values.emplace_back(e.row, std::round(e.display / factor));
                }
                m_document.editNumbers(m_module, values,
                                       [address = m_document.module(m_module).address] {
                                           return tr("module %1 linearisation curve").arg(address);
                                       });
            });
}

std::optional<double> CurveBinding::displayOf(const dev::ParamMeta &row) const
{
    const auto value = m_document.value(m_module, &row);
    if (!value || dev::isText(*value))
        return std::nullopt;
    return dev::toDisplay(row, dev::rawNumber(*value));
}

void CurveBinding::setModule(int module)
{
    m_module = module;
    reload();
}

void CurveBinding::reload()
{
    if (m_module < 0 || m_module >= m_document.moduleCount()) {
        m_curves.setCurves({});
        emit moduleShown(-1);
        return;
    }
    const ParamModule &m = m_document.module(m_module);
    m_curves.setDictionary(*m.dictionary, dev::majorVersion(m.version), m.mode);
    m_curves.setValues([this](const dev::ParamMeta &row) { return displayOf(row); });
    emit moduleShown(m.address);
}

} // namespace vt::model
