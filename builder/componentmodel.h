// SPDX-License-Identifier: MIT
#pragma once

#include "rtcprofile.h"

#include <QObject>

#include <variant>

namespace Builder {

/// The fields of the Builder's "Basic" page.
enum class BasicField {
    Name,
    Description,
    Version,
    Vendor,
    Category,
    ComponentType,
    ActivityType,
    MaxInstances,
    ExecutionType,
    ExecutionRate,
    ComponentKind, ///< `rtc:componentKind`, e.g. DataFlowComponent (check boxes on the page)
    Abstract, ///< `rtc:abstract`, a longer description
    RtcType, ///< `rtc:rtcType`, free text
};

/// The lists of a component that the editor shows as tables.
enum class Part { DataPort, ServicePort, Configuration };

/// One element of a Part's list.
using PartItem
    = std::variant<Profile::RtcDataPort, Profile::RtcServicePort, Profile::RtcConfiguration>;

/**
 * The editing model of one component (RTC Builder's editor): holds the RtcProfile value and is
 * the only way the editor changes it. Each setter announces its change, so that views only
 * listen and undo commands only call this public API.
 *
 * List elements (data ports, service ports, configuration parameters) are addressed by their
 * position in the profile's list. Names cannot serve as ids while editing, because a name the
 * user is typing may collide with another one (duplicates are shown as problems, never refused);
 * the undo stack keeps positions valid, since a command is undone exactly in the state its redo
 * left behind. Every list signal carries the element's name as well.
 */
class ComponentModel : public QObject
{
    Q_OBJECT

public:
    explicit ComponentModel(Profile::RtcProfile profile = Profile::RtcProfile::createDefault(),
                            QObject *parent = nullptr);

    const Profile::RtcProfile &profile() const { return m_profile; }
    /// Replaces everything (RTC.xml page, revert); announced as profileAboutToBeReset/Reset.
    void setProfile(const Profile::RtcProfile &profile);

    // ---- basic information
    /// The field's value; nothing when an optional attribute is absent.
    std::optional<QString> basicField(BasicField field) const;
    /// Sets a field; for a required field an absent value is stored as empty text.
    void setBasicField(BasicField field, const std::optional<QString> &value);
    /// The component id (`RTC:vendor:category:name:version`).
    QString componentId() const { return m_profile.id; }
    void setComponentId(const QString &id);

    /// Optional in the schema (description, max instances, execution rate, abstract, RTC type).
    static bool isOptional(BasicField field);
    /// Part of the component id (name, vendor, category, version).
    static bool isIdPart(BasicField field);
    /// The user-visible name of a field, e.g. "execution rate".
    static QString fieldLabel(BasicField field);
    /// The id `profile` gets when `field` is set to `value` and its id follows its basic info;
    /// an id that does not follow the basic info (hand-edited files) is left as it is.
    static QString idAfterEdit(const Profile::RtcProfile &profile, BasicField field,
                               const QString &value);

    // ---- actions, documentation, language
    /// The entry of an action; nothing when the file has none.
    std::optional<Profile::RtcActionStatus> action(Profile::RtcAction action) const;
    void setAction(Profile::RtcAction action,
                   const std::optional<Profile::RtcActionStatus> &status);
    /// `rtcDoc:Doc` of the basic information (Documentation page).
    void setComponentDoc(const std::optional<Profile::RtcBasicDoc> &doc);
    /// `rtc:Language` with its targets and libraries (Language/Environment page).
    void setLanguage(const std::optional<Profile::RtcLanguage> &language);

    // ---- lists
    int itemCount(Part part) const;
    PartItem item(Part part, int index) const;
    QString itemName(Part part, int index) const;
    /// The position of the first element called `name`; -1 when there is none.
    int indexOf(Part part, const QString &name) const;
    /// Inserts `item` (of the part's type) at `index` (clamped to the list).
    void insertItem(Part part, int index, const PartItem &item);
    void removeItem(Part part, int index);
    /// Replaces an element (a rename is a replacement with another name).
    void setItem(Part part, int index, const PartItem &item);
    /// Moves an element from `from` to `to` (positions in the list before the move).
    void moveItem(Part part, int from, int to);

signals:
    void basicFieldChanged(Builder::BasicField field);
    void componentIdChanged(const QString &id);
    void actionChanged(Profile::RtcAction action);
    void componentDocChanged();
    void languageChanged();

    /// Before an element is inserted at `index` (views that address elements by position
    /// adjust here, before any other view reacts to the insertion).
    void itemAboutToBeInserted(Builder::Part part, int index);
    void itemInserted(Builder::Part part, int index, const QString &name);
    void itemAboutToBeRemoved(Builder::Part part, int index, const QString &name);
    void itemRemoved(Builder::Part part, int index, const QString &name);
    void itemChanged(Builder::Part part, int index, const QString &oldName, const QString &name);
    void itemAboutToBeMoved(Builder::Part part, int from, int to);
    void itemMoved(Builder::Part part, int from, int to, const QString &name);

    void profileAboutToBeReset();
    void profileReset();

    /// After every change of any kind (the preview and the RTC.xml page follow this one).
    void changed();

private:
    Profile::RtcProfile m_profile;
};

/// The user-visible name of a part ("data port" …).
QString partLabel(Part part);

} // namespace Builder

Q_DECLARE_METATYPE(Builder::BasicField)
Q_DECLARE_METATYPE(Builder::Part)
Q_DECLARE_METATYPE(Profile::RtcAction)
