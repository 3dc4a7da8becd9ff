#pragma once
// The texts of a widget that follow the language (docs/i18n.md): each is set once when
// made and again at every language change. A page keeps one Texts and adds a setter per
// text where it makes the widget:
//     m_texts.add([this] { m_title->setText(tr("Training course")); });
// and its changeEvent() calls m_texts.apply() on QEvent::LanguageChange, then makes
// again what it builds from its state (lists, tables).

#include <functional>
#include <utility>
#include <vector>

namespace i18n {

class Texts {
public:
    /// Sets the text now, and again at every apply().
    void add(std::function<void()> set)
    {
        set();
        m_sets.push_back(std::move(set));
    }
    /// Sets every text again (in the language installed now).
    void apply() const
    {
        for (const auto& set : m_sets) set();
    }

private:
    std::vector<std::function<void()>> m_sets;
};

}  // namespace i18n
