// SPDX-License-Identifier: MIT
// Reads RTC Builder's YAML dialect through the field tables; constraint trees have code of their
// own. Unknown keys are kept as XML extras of the element they belong to.
#include "rtcfields_p.h"
#include "rtcyaml.h"
#include "rtcyamlinternal.h"

#include <QCoreApplication>
#include <QStringDecoder>

namespace Profile {

using namespace RtcYaml;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcYaml", text);
}

/// How many schema children the XML writer gives the element of `value` (which has no extras
/// yet): unknown YAML keys kept as elements go after them.
template<typename T> int schemaChildren(const T &value)
{
    XmlNode node;
    RtcXml::writeFields(node, value);
    return int(node.children.size());
}

/// Records a required part the mapping lacks (under its XML name) and warns about it.
void missingKey(const MapReader &m, const char *key, const QString &schemaName, RtcMissing &missing)
{
    missing.append(schemaName);
    m.context().warn(m.node().Mark(),
                     tr("the required key '%1' is missing").arg(QLatin1String(key)));
}

/// Top-level keys beside `rtcProfile:` have no place in the model; say so instead of dropping
/// them silently.
void warnAboutOtherTopLevelKeys(const YAML::Node &document, Context &context)
{
    for (const auto &entry : document) {
        if (entry.first.IsScalar() && entry.first.Scalar() != "rtcProfile") {
            context.warn(entry.first.Mark(),
                         tr("the top-level key '%1' is not part of an RTC Profile and is not kept")
                             .arg(fromStd(entry.first.Scalar())));
        }
    }
}

/// Reads RTC Builder's YAML by walking the field tables (rtcfields_p.h), keys in table order.
class Reader
{
public:
    explicit Reader(Context &context)
        : m_context(context)
    { }

    /// Unknown keys become XML extras placed after the element's schema children.
    template<typename T> T readElement(const YAML::Node &node)
    {
        MapReader m = reader(node);
        T item;
        item.location = m.location();
        Fields::forEachRow(Fields::RtcElement<T>::fields,
                           [&](const auto &row) { readRow(m, item, row); });
        item.extras = m.extras(schemaChildren(item));
        return item;
    }

private:
    MapReader reader(const YAML::Node &node) { return MapReader(node, m_context); }

    template<typename Row> static Keys keysOf(const Row &row)
    {
        return Keys(row.yamlKey, row.yamlLegacyKeys);
    }

    template<typename T, typename Owner, typename Value>
    void readRow(MapReader &m, T &item, const Fields::Scalar<Owner, Value> &row)
    {
        std::optional<QString> value;
        if constexpr (Fields::Scalar<Owner, Value>::required) {
            if (row.style == Fields::Style::Date)
                value = date(m, row.yamlKey, item.missing);
            else if (row.yamlDefault)
                value = m.scalar(keysOf(row)).value_or(QLatin1String(row.yamlDefault));
            else
                value = m.required(keysOf(row), item.missing, row.xmlName);
        } else {
            value = m.scalar(keysOf(row));
        }
        if (value && row.normalize)
            value = row.normalize(*value);
        if constexpr (Fields::Scalar<Owner, Value>::required)
            item.*row.member = *value;
        else
            item.*row.member = value;
    }

    template<typename T, typename Owner, typename Item>
    void readRow(MapReader &m, T &item, const Fields::Child<Owner, QList<Item>> &row)
    {
        for (const YAML::Node &entry : m.list(keysOf(row)))
            (item.*row.member).append(readElement<Item>(entry));
    }

    template<typename T, typename Owner, typename Item>
    void readRow(MapReader &m, T &item, const Fields::Child<Owner, std::optional<Item>> &row)
    {
        if (const auto child = m.map(keysOf(row)))
            item.*row.member = readElement<Item>(*child);
    }

    /// A missing required mapping is recorded under its XML name and warned about.
    template<typename T, typename Owner, typename Item>
    void readRow(MapReader &m, T &item, const Fields::Child<Owner, Item> &row)
    {
        if (const auto child = m.map(keysOf(row)))
            item.*row.member = readElement<Item>(*child);
        else
            missingKey(m, row.yamlKey, QLatin1String(row.xmlName), item.missing);
    }

    template<typename T, typename Owner>
    void readRow(MapReader &m, T &item, const Fields::TextList<Owner> &row)
    {
        item.*row.member = m.scalarList(keysOf(row));
    }

    void readRow(MapReader &m, RtcProfile &profile,
                 const Fields::Special<Fields::RtcProfileVersion> &)
    {
        profile.version = m.required({"version"}, profile.missing);
    }

    void readRow(MapReader &m, RtcProfile &profile,
                 const Fields::Special<Fields::RtcConfigurationSet> &)
    {
        const auto node = m.map({"configurationSet"});
        if (!node)
            return;
        MapReader set = reader(*node);
        profile.configurationSetLocation = set.location();
        for (const YAML::Node &entry : set.list({"configuration"}))
            profile.configurations.append(readElement<RtcConfiguration>(entry));
        profile.hasConfigurationSet = profile.configurations.isEmpty();
        profile.configurationSetExtras
            = set.extras(int(RtcXml::configurationSetToXml(profile).children.size()));
    }

    void readRow(MapReader &m, RtcActions &actions,
                 const Fields::Special<Fields::RtcActionStatuses> &)
    {
        for (RtcAction action : rtcAllActions()) {
            const QByteArray key = rtcActionKey(action).toLatin1();
            if (const auto status = m.map({key.constData()}))
                actions[action] = readElement<RtcActionStatus>(*status);
        }
    }

    template<typename T>
    void readRow(MapReader &m, T &item, const Fields::Special<Fields::RtcConstraintTree> &)
    {
        item.constraint = constraint(m, 0);
    }

    std::optional<RtcConstraint> constraint(MapReader &m, int depth);
    RtcConstraint constraintOf(const YAML::Node &node, int depth);
    void readUnit(const YAML::Node &node, RtcConstraint &c, int depth);
    void readOperator(const YAML::Node &node, RtcConstraint &c, int depth);
    QString date(MapReader &m, const char *key, RtcMissing &missing);

    Context &m_context;
};

QString Reader::date(MapReader &m, const char *key, RtcMissing &missing)
{
    const auto node = m.take({key});
    if (!node || node->IsNull()) {
        missing.append(QLatin1String(key));
        m_context.warn(m.node().Mark(),
                       tr("the required key '%1' is missing").arg(QLatin1String(key)));
        return {};
    }
    return readDate(*node, m_context).value_or(QString());
}

// ---- constraints

std::optional<RtcConstraint> Reader::constraint(MapReader &m, int depth)
{
    const auto node = m.map({"constraint"});
    if (!node)
        return std::nullopt;
    return constraintOf(*node, depth);
}

RtcConstraint Reader::constraintOf(const YAML::Node &node, int depth)
{
    RtcConstraint c;
    c.location = locationOf(node);
    if (depth > MaxDepth) {
        m_context.error(node.Mark(), tr("constraints nested deeper than %1 levels").arg(MaxDepth));
        return c;
    }
    MapReader m = reader(node);
    std::optional<YAML::Node> type;
    if ((type = m.map({"constraintHashType"})))
        c.kind = RtcConstraintKind::Hash;
    else if ((type = m.map({"constraintListType"})))
        c.kind = RtcConstraintKind::List;
    else if ((type = m.map({"constraintUnitType"})))
        c.kind = RtcConstraintKind::Unit;
    else
        c.kind = RtcConstraintKind::Empty;
    if (type && c.kind == RtcConstraintKind::Unit) {
        readUnit(*type, c, depth);
    } else if (type) {
        MapReader t = reader(*type);
        for (const YAML::Node &item : t.list({"constraint"}))
            c.members.push_back(constraintOf(item, depth + 1));
        c.typeExtras = t.extras(int(c.members.size()));
    }
    c.extras = m.extras(c.kind == RtcConstraintKind::Empty ? 0 : 1);
    return c;
}

void Reader::readUnit(const YAML::Node &node, RtcConstraint &c, int depth)
{
    MapReader m = reader(node);
    c.key = m.scalar({"key"});
    for (int i = int(RtcConstraintOperator::Not); i <= int(RtcConstraintOperator::Between); ++i) {
        const auto op = RtcConstraintOperator(i);
        QByteArray key = rtcConstraintOperatorElementName(op).toLatin1();
        key[0] = char(QChar::toLower(key[0]));
        if (const auto value = m.map({key.constData()})) {
            c.op = op;
            readOperator(*value, c, depth);
            break;
        }
    }
    c.typeExtras = m.extras(c.op == RtcConstraintOperator::None ? 0 : 1);
}

void Reader::readOperator(const YAML::Node &node, RtcConstraint &c, int depth)
{
    MapReader m = reader(node);
    switch (c.op) {
    case RtcConstraintOperator::Not:
    case RtcConstraintOperator::And:
    case RtcConstraintOperator::Or:
        for (const YAML::Node &item : m.list({"constraint"}))
            c.members.push_back(constraintOf(item, depth + 1));
        break;
    case RtcConstraintOperator::IsNull:
        c.literal = m.required({"propertyIsNull"}, c.missing);
        break;
    case RtcConstraintOperator::Like:
        c.literal = m.required({"literal"}, c.missing, "Literal");
        c.wildCard = m.scalar({"wildCard"});
        c.singleChar = m.scalar({"singleChar"});
        c.escapeChar = m.scalar({"escapeChar"});
        break;
    case RtcConstraintOperator::Between:
        c.literal = m.required({"lowerBoundary"}, c.missing, "LowerBoundary");
        c.upperBoundary = m.required({"upperBoundary"}, c.missing, "UpperBoundary");
        break;
    default:
        c.literal = m.required({"literal"}, c.missing, "Literal");
        // EMF leaves out attributes at their default: no matchCase means false.
        c.matchCase
            = RtcXml::normalizedBoolean(m.scalar({"matchCase"}).value_or(QStringLiteral("false")));
        break;
    }
    RtcConstraint bare = c;
    bare.operatorExtras = {};
    bare.typeExtras = {};
    const XmlNode element = RtcXml::constraintToXml(bare);
    c.operatorExtras = m.extras(int(element.children.front().children.front().children.size()));
}

/// Finds the first byte that is not UTF-8 (yaml-cpp would accept it silently).
bool checkUtf8(const QByteArray &data, Context &context)
{
    int line = 0;
    qsizetype start = 0;
    while (start <= data.size()) {
        qsizetype end = data.indexOf('\n', start);
        if (end < 0)
            end = data.size();
        QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
        const QString text = decoder.decode(data.mid(start, end - start));
        if (decoder.hasError()) {
            YAML::Mark mark;
            mark.line = line;
            mark.column = int(qMax<qsizetype>(text.indexOf(QChar::ReplacementCharacter), 0));
            context.error(mark, tr("invalid UTF-8 byte sequence"));
            return false;
        }
        ++line;
        start = end + 1;
    }
    return true;
}

std::optional<YAML::Node> parse(const QByteArray &data, Context &context)
{
    try {
        return YAML::Load(data.toStdString());
    } catch (const YAML::Exception &e) {
        context.error(e.mark, tr("YAML syntax error: %1").arg(fromStd(e.msg)));
    } catch (const std::exception &e) {
        context.error(YAML::Mark::null_mark(),
                      tr("cannot read the YAML text: %1").arg(QString::fromLocal8Bit(e.what())));
    }
    return std::nullopt;
}

} // namespace

std::optional<RtcProfile> readRtcYaml(const QByteArray &data, const QString &fileName,
                                      Diagnostics *diagnostics)
{
    Context context(fileName, diagnostics);
    if (!checkUtf8(data, context))
        return std::nullopt;
    const std::optional<YAML::Node> document = parse(data, context);
    if (!document)
        return std::nullopt;
    if (!document->IsMap() || !(*document)["rtcProfile"]) {
        // An empty document has no position; the problem is then at its start.
        const YAML::Mark mark = document->Mark().is_null() ? YAML::Mark() : document->Mark();
        context.error(mark, tr("not an RTC Profile: expected a top-level 'rtcProfile:' mapping"));
        return std::nullopt;
    }
    try {
        warnAboutOtherTopLevelKeys(*document, context);
        RtcProfile profile = Reader(context).readElement<RtcProfile>((*document)["rtcProfile"]);
        if (context.failed())
            return std::nullopt;
        return profile;
    } catch (const YAML::Exception &e) {
        context.error(e.mark, tr("cannot read the YAML text: %1").arg(fromStd(e.msg)));
    }
    return std::nullopt;
}

} // namespace Profile
