// Station profiles: JSON round trip, every kind of bad file refused with where and
// why (never half-read), checks against a model's drives, the default profile.
#include "trainer/station/profile.h"
#include "trainer/station/profile_store.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace trainer;

namespace {

QList<DriveInfo> linerDrives()
{
    const char* names[] = {"GIRO PLUMA", "LEVANTE PLUMA", "EXTENSIÓN", "GIRO MUÑECA", "LEVANTE MUÑECA",
                           "ROTACIÓN MUÑECA", "PISTÓN", "GARRA SUPERIOR", "GARRA INFERIOR"};
    QList<DriveInfo> d;
    for (int i = 0; i < 9; ++i) d.append({i, i + 1, QString::fromUtf8(names[i])});
    return d;
}

StationProfile sample()
{
    StationProfile p;
    p.name = "Consola";
    p.model = "liner_manipulator";
    p.description = "ocho palancas";
    p.devices.append({"serial:/dev/ttyACM0", 57600});
    ChannelCalibration c{3, 515, 1019, 0.04, 0.06};
    c.captured = true;
    c.filterHz = 20;
    p.calibrations.append({"serial", 0, c});
    p.always.append({"keyboard", 0, 1, 1.0, 1});
    p.banks.append({"Pluma", {{"gamepad", 9}}, {{"gamepad", 0, 1, 0.5, -1}}});
    p.banks.append({"Muñeca", {{"gamepad", 10}}, {{"gamepad", 1, 4, 1.0, 1}}});
    p.nextBank = {"gamepad", 4};
    p.translations["en"] = {{"Consola", "Console"}, {"Pluma", "Boom"}};
    return p;
}

bool parse(const QByteArray& json, QList<ProfileIssue>& issues)
{
    StationProfile out;
    out.name = "untouched";
    const bool ok = StationProfile::fromJson(json, out, issues);
    if (!ok) {
        EXPECT_EQ(out.name, "untouched");  // never half-read
    }
    return ok;
}

}  // namespace

TEST(Profile, JsonRoundTrip)
{
    const StationProfile p = sample();
    StationProfile back;
    QList<ProfileIssue> issues;
    ASSERT_TRUE(StationProfile::fromJson(p.toJson(), back, issues));
    EXPECT_TRUE(issues.isEmpty());
    EXPECT_EQ(back, p);
}

// the texts a person reads, per language, keyed by the text as written; the name stays
TEST(Profile, TranslationsGiveTheTextsInALanguageAndOthersStayAsWritten)
{
    const StationProfile p = sample();
    EXPECT_EQ(p.localized("Consola", "en"), "Console");
    EXPECT_EQ(p.localized("Pluma", "en"), "Boom");
    EXPECT_EQ(p.localized("Muñeca", "en"), "Muñeca");  // no entry: as written
    EXPECT_EQ(p.localized("Pluma", "es"), "Pluma");
    EXPECT_EQ(p.localized("Pluma", "fr"), "Pluma");
    StationProfile back;
    QList<ProfileIssue> issues;
    const QByteArray bad = QByteArray(p.toJson()).replace("\"Boom\"", "7");
    EXPECT_FALSE(StationProfile::fromJson(bad, back, issues));
    ASSERT_EQ(issues.size(), 1);
    EXPECT_EQ(issues.first().where, "translations.en");
    issues.clear();
    EXPECT_FALSE(StationProfile::fromJson(QByteArray(p.toJson()).replace("\"Console\"", "[]"), back, issues));
}

TEST(Profile, CorruptJsonSaysLineAndColumn)
{
    QByteArray json = sample().toJson();
    json.insert(json.indexOf("\"name\""), "{{");
    QList<ProfileIssue> issues;
    EXPECT_FALSE(parse(json, issues));
    ASSERT_EQ(issues.size(), 1);
    EXPECT_TRUE(issues[0].where.contains("line")) << issues[0].text().toStdString();
    EXPECT_TRUE(issues[0].where.contains("column"));
}

TEST(Profile, FutureVersionIsRefusedWithAnExplanation)
{
    QByteArray json = sample().toJson();
    json.replace("\"version\": 1", "\"version\": 7");
    QList<ProfileIssue> issues;
    EXPECT_FALSE(parse(json, issues));
    ASSERT_EQ(issues.size(), 1);
    EXPECT_EQ(issues[0].where, "version");
    EXPECT_TRUE(issues[0].message.contains("7"));
    EXPECT_TRUE(issues[0].message.contains("newer"));
}

TEST(Profile, WrongTypesAndOtherFormatsAreRefusedWithAPath)
{
    QList<ProfileIssue> issues;
    EXPECT_FALSE(parse(R"({"format":"something-else","version":1,"name":"x"})", issues));
    EXPECT_EQ(issues.value(0).where, "format");
    issues.clear();
    EXPECT_FALSE(parse(R"([1,2])", issues));
    issues.clear();
    EXPECT_FALSE(parse(R"({"format":"padrob-station-profile","version":1,"name":"x",
                          "banks":[{"name":"a","mappings":[{"device":"gamepad","axis":"left","drive":1}]}]})",
                       issues));
    ASSERT_EQ(issues.size(), 1);
    EXPECT_EQ(issues[0].where, "banks[0].mappings[0]");
    EXPECT_TRUE(issues[0].message.contains("axis"));
    issues.clear();
    EXPECT_FALSE(parse(R"({"format":"padrob-station-profile","version":1,"name":"x",
                          "calibrations":[{"device":"serial","axis":0,"min":10,"centre":5,"max":20}]})",
                       issues));
    EXPECT_EQ(issues.value(0).where, "calibrations[0]");
    issues.clear();
    EXPECT_FALSE(parse(R"({"format":"padrob-station-profile","version":1})", issues));
    EXPECT_TRUE(issues.value(0).message.contains("name"));
}

TEST(Profile, CheckWarnsOfDrivesTheModelLacksAndRefusesBadGains)
{
    StationProfile p = sample();
    p.banks[0].mappings.append({"gamepad", 2, 42, 1.0, 1});
    p.banks[1].mappings.append({"gamepad", 3, 2, -2.0, 3});
    const QList<ProfileIssue> issues = p.check(linerDrives());
    ASSERT_EQ(issues.size(), 3);
    EXPECT_EQ(issues[0].where, "banks[0].mappings[1]");
    EXPECT_FALSE(issues[0].error);
    EXPECT_TRUE(issues[0].message.contains("42"));
    EXPECT_TRUE(issues[1].error);  // sign
    EXPECT_TRUE(issues[2].error);  // gain
    EXPECT_TRUE(sample().check(linerDrives()).isEmpty());
}

TEST(Profile, IssuesOfAProfileReadFromAFileNameTheFile)
{
    QTemporaryDir dir;
    StationProfile p = sample();
    p.banks[1].mappings.append({"gamepad", 3, 2, 99.0, 1});  // a gain out of range
    const QString file = dir.filePath("console.json");
    QString error;
    ASSERT_TRUE(ProfileStore::exportFile(p, file, false, &error)) << error.toStdString();
    ProfileStore store(dir.filePath("store"));
    StationProfile read;
    QList<ProfileIssue> issues;
    ASSERT_TRUE(store.resolve(dir.filePath("liner_manipulator.pad"), file, linerDrives(), read, issues));
    EXPECT_EQ(read, p);  // the file it came from is no part of the profile
    const QList<ProfileIssue> found = read.check(linerDrives());
    ASSERT_EQ(found.size(), 1);
    EXPECT_TRUE(found[0].error);
    EXPECT_EQ(found[0].where, file + ": banks[1].mappings[1]") << found[0].text().toStdString();
    EXPECT_TRUE(found[0].message.contains("gain"));
}

TEST(Profile, DefaultProfileMapsKeysOneToOneAndTheGamepadInBanksOfFour)
{
    const StationProfile p = StationProfile::defaultFor("liner_manipulator", linerDrives());
    EXPECT_TRUE(p.check(linerDrives()).isEmpty());
    ASSERT_EQ(p.always.size(), 9);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(p.always[i].drive, i + 1);
    ASSERT_EQ(p.banks.size(), 3);
    EXPECT_EQ(p.banks[0].mappings.size(), 4);
    EXPECT_EQ(p.banks[2].mappings.size(), 1);
    EXPECT_TRUE(p.nextBank.isSet());
    QList<int> drives;
    for (const Bank& b : p.banks)
        for (const Mapping& m : b.mappings) drives.append(m.drive);
    EXPECT_EQ(drives, (QList<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
    StationProfile back;
    QList<ProfileIssue> issues;
    ASSERT_TRUE(StationProfile::fromJson(p.toJson(), back, issues));
    EXPECT_EQ(back, p);
}

#include "trainer/station/profile_store.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

namespace {

void write(const QString& path, const QByteArray& data)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(data);
}

QByteArray read(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

TEST(ProfileStore, SavesPerModelAndNeverOverwritesSilently)
{
    QTemporaryDir dir;
    ProfileStore store(dir.filePath("config"));
    const QString model = dir.filePath("models/liner_manipulator.pad");
    StationProfile p = sample();
    QString error;
    ASSERT_TRUE(store.save(model, p, ProfileStore::SaveMode::CreateOnly, &error)) << error.toStdString();
    const QString path = dir.filePath("config/liner_manipulator/Consola.json");
    ASSERT_TRUE(QFileInfo::exists(path));
    const QByteArray before = read(path);
    p.description = "changed";
    EXPECT_FALSE(store.save(model, p, ProfileStore::SaveMode::CreateOnly, &error));
    EXPECT_TRUE(error.contains("Consola"));
    EXPECT_EQ(read(path), before);
    ASSERT_TRUE(store.save(model, p, ProfileStore::SaveMode::Overwrite, &error));
    StationProfile back;
    QList<ProfileIssue> issues;
    ASSERT_TRUE(store.load(model, "Consola", back, issues));
    EXPECT_EQ(back.description, "changed");
    EXPECT_EQ(store.list(dir.filePath("models/excavator.pad")).size(), 0);
}

TEST(ProfileStore, UnreadableFilesAreListedWithTheirProblemAndKeptAsideWhenReplaced)
{
    QTemporaryDir dir;
    ProfileStore store(dir.filePath("config"));
    const QString model = dir.filePath("m/crane.pad");
    write(dir.filePath("config/crane/Broken.json"), "{ \"format\": \"padrob-station-profile\", oops");
    QByteArray future = sample().toJson();
    future.replace("\"version\": 1", "\"version\": 9");
    future.replace("\"Consola\"", "\"Future\"");
    write(dir.filePath("config/crane/Future.json"), future);
    const QList<StoredProfile> list = store.list(model);
    ASSERT_EQ(list.size(), 2);
    EXPECT_FALSE(list[0].readable);
    EXPECT_TRUE(list[0].problem.contains("line")) << list[0].problem.toStdString();
    EXPECT_FALSE(list[1].readable);
    EXPECT_TRUE(list[1].problem.contains("newer"));
    StationProfile p = sample();
    p.name = "Broken";
    QString error;
    ASSERT_TRUE(store.save(model, p, ProfileStore::SaveMode::Overwrite, &error)) << error.toStdString();
    const QStringList aside = QDir(dir.filePath("config/crane")).entryList({"Broken.json.bak-*"});
    ASSERT_EQ(aside.size(), 1);
    EXPECT_TRUE(read(dir.filePath("config/crane/" + aside[0])).contains("oops"));
}

TEST(ProfileStore, ShippedProfilesAreReadOnlyAndShadowedByUserCopies)
{
    QTemporaryDir dir;
    ProfileStore store(dir.filePath("config"));
    const QString model = dir.filePath("models/liner_manipulator.pad");
    StationProfile shipped = sample();
    shipped.name = "Gamepad";
    write(dir.filePath("models/liner_manipulator.station/gamepad.json"), shipped.toJson());
    QList<StoredProfile> list = store.list(model);
    ASSERT_EQ(list.size(), 1);
    EXPECT_TRUE(list[0].shipped);
    QString error;
    EXPECT_FALSE(store.remove(model, "Gamepad", &error));
    shipped.description = "mine";
    ASSERT_TRUE(store.save(model, shipped, ProfileStore::SaveMode::CreateOnly, &error));
    list = store.list(model);
    ASSERT_EQ(list.size(), 1);
    EXPECT_FALSE(list[0].shipped);
    StationProfile back;
    QList<ProfileIssue> issues;
    ASSERT_TRUE(store.load(model, "Gamepad", back, issues));
    EXPECT_EQ(back.description, "mine");
    ASSERT_TRUE(store.remove(model, "Gamepad", &error));
    ASSERT_TRUE(store.load(model, "Gamepad", back, issues));
    EXPECT_EQ(back.description, "ocho palancas");
}

TEST(ProfileStore, ImportTakesAFreeNameAndRefusesBadFiles)
{
    QTemporaryDir dir;
    ProfileStore store(dir.filePath("config"));
    const QString model = dir.filePath("m/liner_manipulator.pad");
    const QString file = dir.filePath("usb/consola.json");
    write(file, sample().toJson());
    QList<ProfileIssue> issues;
    EXPECT_EQ(store.importFile(file, model, issues), "Consola");
    EXPECT_EQ(store.importFile(file, model, issues), "Consola (2)");
    EXPECT_TRUE(issues.isEmpty());
    QByteArray future = sample().toJson();
    future.replace("\"version\": 1", "\"version\": 2");
    write(file, future);
    EXPECT_EQ(store.importFile(file, model, issues), "");
    ASSERT_FALSE(issues.isEmpty());
    EXPECT_TRUE(issues[0].text().contains("newer"));
    QString error;
    EXPECT_FALSE(ProfileStore::exportFile(sample(), file, false, &error));
    EXPECT_TRUE(ProfileStore::exportFile(sample(), file, true, &error));
    EXPECT_EQ(ProfileStore::fileNameFor("a/b:c"), "a_b_c.json");
}

#include "solver/pipeline.h"

TEST(ShippedProfiles, LinerManipulatorGamepadAndConsoleLoadAndMapEveryDrive)
{
    const QString modelPath = PADROB_SOURCE_DIR "/models/liner_manipulator.pad";
    const solver::CompiledModel loaded = solver::compileFile(modelPath.toStdString());
    const auto model = loaded.model;
    ASSERT_TRUE(model);
    const QList<DriveInfo> drives = drivesOf(*model);
    ASSERT_EQ(drives.size(), 9);
    EXPECT_EQ(drives[1].label(), "C 2 LEVANTE PLUMA");

    QTemporaryDir dir;
    ProfileStore store(dir.filePath("config"));
    const QList<StoredProfile> list = store.list(modelPath);
    QStringList names;
    for (const StoredProfile& s : list) {
        EXPECT_TRUE(s.shipped);
        EXPECT_TRUE(s.readable) << s.problem.toStdString();
        names.append(s.name);
    }
    EXPECT_EQ(names, (QStringList{"Console (8 levers)", "Gamepad"}));
    for (const QString& name : names) {
        StationProfile p;
        QList<ProfileIssue> issues;
        ASSERT_TRUE(store.load(modelPath, name, p, issues));
        EXPECT_TRUE(p.check(drives).isEmpty()) << name.toStdString() << ": " << p.check(drives).value(0).text().toStdString();
        QSet<int> mapped;
        for (const Mapping& m : p.always) mapped.insert(m.drive);
        for (const Bank& b : p.banks)
            for (const Mapping& m : b.mappings) mapped.insert(m.drive);
        EXPECT_EQ(mapped.size(), 9) << name.toStdString();
    }
    StationProfile console;
    QList<ProfileIssue> issues;
    ASSERT_TRUE(store.load(modelPath, "Console (8 levers)", console, issues));
    QSet<int> levers;  // eight levers, one valve each (lever 8: both claws)
    for (const Mapping& m : console.always) levers.insert(m.axis);
    EXPECT_EQ(levers.size(), 8);
    StationProfile pad;
    ASSERT_TRUE(store.load(modelPath, "Gamepad", pad, issues));
    EXPECT_EQ(pad.banks.size(), 2);
    // every text a person reads in Spanish too (issue 25, item 12), in both machines' files
    for (const QString& machine : {QStringLiteral("liner_manipulator"), QStringLiteral("liner_manipulator_fluid")}) {
        const QString path = PADROB_SOURCE_DIR "/models/" + machine + ".pad";
        for (const QString& name : names) {
            StationProfile p;
            ASSERT_TRUE(store.load(path, name, p, issues)) << machine.toStdString();
            QStringList texts{p.name, p.description};
            for (const Bank& b : p.banks) texts << b.name;
            for (const QString& text : texts)
                EXPECT_NE(p.localized(text, "es"), text) << machine.toStdString() << ": " << text.toStdString();
        }
    }
    EXPECT_EQ(pad.localized("Gamepad", "es"), "Mando");
    EXPECT_EQ(pad.localized("Wrist", "es"), "Muñeca");
}
