// SPDX-License-Identifier: MIT
#pragma once
// Fills a profile model through its field tables, for the tests that check that every row of a
// table survives writing and reading.

#include "fieldtable_p.h"

/**
 * Gives every field of an element, as its field table lists it, a value of its own (lists get two
 * entries, optional children are present), down through the child elements' tables. A row added
 * to a table later is filled, and so checked, without touching the tests.
 *
 * `Element` is the table template (Fields::RtsElement, Fields::RtcElement); `Derived` fills the
 * table's Special rows with `fillSpecial(item, row)`.
 */
template<typename Derived, template<typename> class Element> class FieldTableFiller
{
public:
    template<typename T> void fill(T &item)
    {
        Profile::Fields::forEachRow(Element<T>::fields,
                                    [&](const auto &row) { fillRow(item, row); });
    }

    int scalarCount() const { return m_count; }

protected:
    QString next(Profile::Fields::Style style)
    {
        using Profile::Fields::Style;
        ++m_count;
        switch (style) {
        case Style::Number:
            return QStringLiteral("%1.5").arg(m_count);
        case Style::Boolean:
            return Profile::booleanText(m_count % 2 == 0);
        case Style::Date:
            return QStringLiteral("2024-05-%1T10:20:%2.250+09:00")
                .arg(m_count % 28 + 1, 2, 10, QLatin1Char('0'))
                .arg(m_count % 60, 2, 10, QLatin1Char('0'));
        case Style::Text:
            break;
        }
        return QStringLiteral("value %1").arg(m_count);
    }

    template<typename T, typename Owner, typename Value>
    void fillRow(T &item, const Profile::Fields::Scalar<Owner, Value> &row)
    {
        item.*row.member = next(row.style);
    }

    template<typename T, typename Owner, typename Item>
    void fillRow(T &item, const Profile::Fields::Child<Owner, QList<Item>> &row)
    {
        for (int i = 0; i < 2; ++i)
            fill((item.*row.member).emplace_back());
    }

    template<typename T, typename Owner, typename Item>
    void fillRow(T &item, const Profile::Fields::Child<Owner, std::optional<Item>> &row)
    {
        fill((item.*row.member).emplace());
    }

    template<typename T, typename Owner, typename Item>
    void fillRow(T &item, const Profile::Fields::Child<Owner, Item> &row)
    {
        fill(item.*row.member);
    }

    template<typename T, typename Owner>
    void fillRow(T &item, const Profile::Fields::TextList<Owner> &row)
    {
        using Profile::Fields::Style;
        item.*row.member = {next(Style::Text), next(Style::Text)};
    }

    template<typename T, typename... Rows>
    void fillRow(T &item, const Profile::Fields::YamlGroup<Rows...> &group)
    {
        Profile::Fields::forEachRow(group.rows, [&](const auto &row) { fillRow(item, row); });
    }

    template<typename T, typename Tag>
    void fillRow(T &item, const Profile::Fields::Special<Tag> &row)
    {
        static_cast<Derived *>(this)->fillSpecial(item, row);
    }

private:
    int m_count = 0;
};
