// SPDX-License-Identifier: MIT
// Shared by the canvas tests: loading the fixture system into a model.
#pragma once

#include "systemfile.h"
#include "systemmodel.h"

#include <QTest>

#include <memory>

namespace SeCanvasTest {

inline QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/secanvas/")) + name;
}

/// The fixture system with the RTC profiles its components point at; null on failure.
inline std::unique_ptr<SystemEditor::SystemModel> loadModel(const QString &path
                                                            = dataPath(QStringLiteral("system.xml")))
{
    Profile::Diagnostics diagnostics;
    std::optional<SystemEditor::LoadedSystem> loaded
        = SystemEditor::loadSystemFile(path, &diagnostics);
    if (!loaded)
        return nullptr;
    auto model = std::make_unique<SystemEditor::SystemModel>();
    model->setProfile(loaded->profile, loaded->rtcProfiles);
    return model;
}

} // namespace SeCanvasTest
