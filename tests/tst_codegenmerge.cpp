// SPDX-License-Identifier: MIT
#include "codegenerator.h"
#include "idltypelibrary.h"
#include "profileio.h"
#include "regionmerge.h"

#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTest>

#include <map>

using namespace Codegen;
using namespace Profile;

// Property test of the region merge on real generated files: a seeded generator makes random
// user edits outside and inside the `<rtc-template>` blocks of a generated file and random
// changes to the profile; merging the regenerated file into the edited one must keep every
// user line outside the blocks byte for byte and make every block equal the new generation.
class TestCodegenMerge : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void userEditsSurviveRegeneration();
    void mergeOfUneditedFileIsTheFreshFile();

private:
    struct Variant
    {
        QString label;
        std::map<QString, QString> files; ///< path → text, only files with blocks
    };
    std::optional<Variant> generateVariant(const RtcProfile &profile, const QString &label);
    RtcProfile mutatedProfile(QRandomGenerator &random, int index) const;

    IdlModel m_idl;
    RtcProfile m_profile;
    Variant m_base;
    QList<Variant> m_variants;
};

namespace {

constexpr quint32 Seed = 20240304;
constexpr int Variants = 10;
constexpr int Iterations = 400;

/// One line of a file: a marker, a line inside a block (`block` names it) or a user line.
struct Line
{
    QString text;
    QString block; ///< empty outside blocks
    bool marker = false;
    bool byUser = false; ///< typed or changed by the simulated user
};

const QRegularExpression &openMarker()
{
    static const QRegularExpression re(QStringLiteral("<rtc-template block=\"([^\"]*)\">"));
    return re;
}

QList<Line> classify(const QString &text)
{
    QList<Line> lines;
    QString block;
    for (const QString &line : text.split(QLatin1Char('\n'))) {
        const QRegularExpressionMatch open = openMarker().match(line);
        if (open.hasMatch()) {
            lines << Line {line, QString(), true};
            block = open.captured(1);
        } else if (line.contains(QLatin1String("</rtc-template>"))) {
            lines << Line {line, QString(), true};
            block.clear();
        } else {
            lines << Line {line, block, false};
        }
    }
    return lines;
}

QString join(const QList<Line> &lines)
{
    QStringList texts;
    for (const Line &line : lines)
        texts << line.text;
    return texts.join(QLatin1Char('\n'));
}

/// The text with every block body removed (markers kept): what the user owns.
QString outsideBlocks(const QString &text)
{
    QStringList kept;
    for (const Line &line : classify(text)) {
        if (line.block.isEmpty())
            kept << line.text;
    }
    return kept.join(QLatin1Char('\n'));
}

/// Block name → body lines, in file order; a name that occurs twice keeps both bodies.
QMultiMap<QString, QString> blockBodies(const QString &text)
{
    QMultiMap<QString, QString> bodies;
    QString current;
    QString body;
    for (const Line &line : classify(text)) {
        const QRegularExpressionMatch open = openMarker().match(line.text);
        if (open.hasMatch()) {
            current = open.captured(1);
            body.clear();
        } else if (line.marker && !current.isEmpty()) {
            bodies.insert(current, body);
            current.clear();
        } else if (!current.isEmpty()) {
            body += line.text + QLatin1Char('\n');
        }
    }
    return bodies;
}

/// Applies 1–6 random user edits; returns the lines the user left outside / inside blocks.
QString editAsUser(const QString &generated, QRandomGenerator &random, int iteration,
                   QStringList *addedOutside, QStringList *addedInside)
{
    QList<Line> lines = classify(generated);
    const int edits = 1 + random.bounded(6);
    for (int e = 0; e < edits; ++e) {
        const QString text = QStringLiteral("user line %1.%2 #%3")
                                 .arg(iteration)
                                 .arg(e)
                                 .arg(random.generate(), 8, 16, QLatin1Char('0'));
        const int kind = random.bounded(4);
        const int at = random.bounded(int(lines.size()));
        const Line here = lines.at(at);
        if (kind == 0) { // insert a user line before `at`: outside when no block encloses it
            const bool inside = !here.block.isEmpty()
                || (here.marker && here.text.contains(QLatin1String("</rtc-template>")));
            lines.insert(at, Line {text, inside ? QStringLiteral("?") : QString(), false, true});
        } else if (here.marker) {
            continue; // the user keeps the markers, or the merge could not find the blocks
        } else if (kind == 1) { // rewrite a line
            lines[at].text
                = (here.block.isEmpty() ? here.text : QString()) + QLatin1Char(' ') + text;
            lines[at].byUser = true;
        } else if (kind == 2 && here.block.isEmpty()) { // delete a line outside the blocks
            lines.removeAt(at);
        } else if (!here.block.isEmpty()) { // append to a line inside a block
            lines[at].text += QLatin1Char(' ') + text;
            lines[at].byUser = true;
        }
    }
    for (const Line &line : std::as_const(lines)) {
        if (line.byUser)
            (line.block.isEmpty() ? addedOutside : addedInside)->append(line.text);
    }
    return join(lines);
}

} // namespace

void TestCodegenMerge::initTestCase()
{
    Diagnostics diagnostics;
    const std::optional<LoadedProfile> loaded = loadProfileFile(
        RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/SampleComp.xml"), &diagnostics);
    QVERIFY(loaded && loaded->rtc);
    m_profile = *loaded->rtc;
    IdlTypeLibrary library(
        {RTSTUDIO_IDL_DIR, RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/idl")});
    m_idl = library.model();
    QElapsedTimer timer;
    timer.start();
    const std::optional<Variant> base = generateVariant(m_profile, QStringLiteral("base"));
    QVERIFY(base);
    m_base = *base;
    QVERIFY(m_base.files.size() >= 8);
    QRandomGenerator random(Seed);
    for (int i = 0; i < Variants; ++i) {
        const std::optional<Variant> variant
            = generateVariant(mutatedProfile(random, i), QStringLiteral("variant %1").arg(i));
        QVERIFY(variant);
        m_variants << *variant;
    }
    qInfo("%d generated variants in %lld ms", Variants + 1, timer.elapsed());
}

std::optional<TestCodegenMerge::Variant>
TestCodegenMerge::generateVariant(const RtcProfile &profile, const QString &label)
{
    Diagnostics diagnostics;
    const auto files = CodeGenerator(profile, m_idl).generate(allTargetLanguages(), &diagnostics);
    if (!files)
        return std::nullopt;
    Variant variant {label, {}};
    for (const GeneratedFile &file : *files) {
        const QString text = QString::fromUtf8(file.content);
        if (!templateRegionNames(text).isEmpty())
            variant.files[file.path] = text;
    }
    return variant;
}

RtcProfile TestCodegenMerge::mutatedProfile(QRandomGenerator &random, int index) const
{
    RtcProfile profile = m_profile;
    const int changes = 1 + random.bounded(4);
    for (int c = 0; c < changes; ++c) {
        switch (random.bounded(6)) {
        case 0:
            profile.basicInfo.description = QStringLiteral("Changed description %1").arg(index);
            break;
        case 1: {
            const RtcAction action = rtcAllActions().at(1 + random.bounded(11));
            RtcActionStatus status = profile.actions[action].value_or(RtcActionStatus());
            status.setImplemented(!status.isImplemented());
            profile.actions[action] = status;
            break;
        }
        case 2: {
            RtcDataPort port;
            port.portType
                = random.bounded(2) ? QStringLiteral("DataInPort") : QStringLiteral("DataOutPort");
            port.name = QStringLiteral("extra%1_%2").arg(index).arg(c);
            port.type = QStringLiteral("RTC::TimedShort");
            port.idlFile = QStringLiteral("BasicDataType.idl");
            profile.dataPorts << port;
            break;
        }
        case 3:
            if (!profile.dataPorts.isEmpty())
                profile.dataPorts.removeAt(random.bounded(int(profile.dataPorts.size())));
            break;
        case 4:
            if (!profile.configurations.isEmpty())
                profile.configurations.first().defaultValue = QString::number(index * 7 + c);
            break;
        default: {
            RtcConfiguration config;
            config.name = QStringLiteral("param%1_%2").arg(index).arg(c);
            config.type = QStringLiteral("double");
            config.defaultValue = QStringLiteral("%1.5").arg(index);
            profile.configurations << config;
            break;
        }
        }
    }
    return profile;
}

void TestCodegenMerge::userEditsSurviveRegeneration()
{
    QElapsedTimer timer;
    timer.start();
    QRandomGenerator random(Seed + 1);
    const QStringList paths = [this] {
        QStringList keys;
        for (const auto &entry : m_base.files)
            keys << entry.first;
        return keys;
    }();
    int checkedInside = 0;
    for (int i = 0; i < Iterations; ++i) {
        const QString path = paths.at(random.bounded(int(paths.size())));
        const Variant &variant = m_variants.at(random.bounded(int(m_variants.size())));
        const auto freshIt = variant.files.find(path);
        if (freshIt == variant.files.end())
            continue; // a file only some profiles have (a servant of a removed interface)
        QStringList addedOutside, addedInside;
        const QString user
            = editAsUser(m_base.files.at(path), random, i, &addedOutside, &addedInside);
        const QString context
            = QStringLiteral("iteration %1, %2, %3").arg(i).arg(path, variant.label);
        const RegionMergeResult result = mergeTemplateRegions(user, freshIt->second);
        QVERIFY2(result.text, qPrintable(context + ": " + result.error));
        // Everything the user owns is kept byte for byte …
        QVERIFY2(outsideBlocks(*result.text) == outsideBlocks(user), qPrintable(context));
        for (const QString &line : std::as_const(addedOutside))
            QVERIFY2(result.text->contains(line), qPrintable(context + ": lost " + line));
        // … every block is the new generation's, and what the user typed inside one is gone.
        QVERIFY2(blockBodies(*result.text) == blockBodies(freshIt->second), qPrintable(context));
        for (const QString &line : std::as_const(addedInside)) {
            QVERIFY2(!result.text->contains(line), qPrintable(context + ": kept " + line));
            ++checkedInside;
        }
    }
    QVERIFY(checkedInside > Iterations / 4);
    // Speed is the benchmarks' business (a sanitizer build on a busy machine takes twice as long).
    qInfo("%d merges in %lld ms", Iterations, timer.elapsed());
}

void TestCodegenMerge::mergeOfUneditedFileIsTheFreshFile()
{
    int compared = 0;
    for (const Variant &variant : std::as_const(m_variants)) {
        for (const auto &[path, fresh] : variant.files) {
            const auto base = m_base.files.find(path);
            if (base == m_base.files.end())
                continue;
            const RegionMergeResult result = mergeTemplateRegions(base->second, fresh);
            QVERIFY2(result.text, qPrintable(path));
            // Where the profile change only touched generator-owned blocks, merging the
            // unedited earlier file must give exactly the fresh one.
            if (outsideBlocks(base->second) != outsideBlocks(fresh))
                continue;
            QVERIFY2(*result.text == fresh, qPrintable(variant.label + ", " + path));
            ++compared;
        }
    }
    QVERIFY(compared > Variants);
}

QTEST_GUILESS_MAIN(TestCodegenMerge)
#include "tst_codegenmerge.moc"
