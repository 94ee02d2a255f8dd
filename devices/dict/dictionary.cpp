#include "dictionary.h"

namespace vt::dev {

const ParamMeta *Dictionary::find(const std::string &name) const
{
    const auto it = m_byName.find(name);
    return it == m_byName.end() ? nullptr : &params[it->second];
}

const ParamMeta *Dictionary::findId(int id) const
{
    const auto it = m_byId.find(id);
    return it == m_byId.end() ? nullptr : &params[it->second];
}

const ParamMeta *Dictionary::findIndPnu(int ind, int pnu, int instance) const
{
    const auto it = m_byIndPnu.find({ind, pnu, instance});
    return it == m_byIndPnu.end() ? nullptr : &params[it->second];
}

const ParamMeta *Dictionary::stateControlWord() const
{
    if (protocol != DeviceProtocol::Dsp408 && protocol != DeviceProtocol::Hart)
        return nullptr;
    const ParamMeta *control = find("db_ControlWord");
    const ParamMeta *status = find("db_StatusWord");
    return control && control->writable() && status && status->readable() ? control : nullptr;
}

void Dictionary::buildIndex()
{
    m_byName.clear();
    m_byId.clear();
    m_byIndPnu.clear();
    for (std::size_t i = 0; i < params.size(); ++i) {
        const ParamMeta &p = params[i];
        m_byName.emplace(p.name, i);
        if (p.id)
            m_byId.emplace(*p.id, i);
        if (p.ind && p.pnu)
            m_byIndPnu.emplace(std::make_tuple(*p.ind, *p.pnu, p.instance), i);
    }
}

std::string DictionaryError::text() const
{
    std::string out = file;
    if (!row.empty())
        out += ", row " + row;
    return out + ": " + message;
}

std::vector<std::string> DictionarySet::families() const
{
    std::vector<std::string> out;
    for (const auto &[id, dict] : m_families)
        if (!dict->abstract)
            out.push_back(id);
    return out;
}

const Dictionary *DictionarySet::find(const std::string &family) const
{
    const auto it = m_families.find(family);
    return it == m_families.end() ? nullptr : it->second.get();
}

void DictionarySet::add(std::shared_ptr<const Dictionary> dictionary)
{
    const std::string id = dictionary->family;
    m_families[id] = std::move(dictionary);
}

} // namespace vt::dev
