<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ja_JP">
<context>
    <name>AddComponentCommand</name>
    <message>
        <location filename="../../systemeditor/instancecommands.cpp" line="+43"/>
        <source>Add %1</source>
        <translation>%1 を追加</translation>
    </message>
</context>
<context>
    <name>AutoLayout</name>
    <message>
        <location filename="../../systemeditor/autolayout.cpp" line="+133"/>
        <source>Auto Layout</source>
        <translation>自動レイアウト</translation>
    </message>
</context>
<context>
    <name>Builder::ActionTableModel</name>
    <message>
        <location filename="../../builder/actiontablemodel.cpp" line="+65"/>
        <source>onInitialize is always implemented.</source>
        <translation>onInitialize は常に実装されます。</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Callback</source>
        <translation>コールバック</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Description</source>
        <translation>説明</translation>
    </message>
</context>
<context>
    <name>Builder::ActivityPage</name>
    <message>
        <location filename="../../builder/activitypage.cpp" line="+69"/>
        <source>&amp;Description:</source>
        <translation>説明(&amp;D)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Precondition:</source>
        <translation>事前条件(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;ostcondition:</source>
        <translation>事後条件(&amp;O)：</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Callback %1</source>
        <translation>コールバック %1</translation>
    </message>
</context>
<context>
    <name>Builder::BasicPage</name>
    <message>
        <location filename="../../builder/basicpage.cpp" line="+181"/>
        <source>Component</source>
        <translation>コンポーネント</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Name:</source>
        <translation>名前(&amp;N)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Description:</source>
        <translation>説明(&amp;D)：</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+260"/>
        <source>(none)</source>
        <translation>（なし）</translation>
    </message>
    <message>
        <location line="-259"/>
        <source>&amp;Version:</source>
        <translation>バージョン(&amp;V)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>V&amp;endor:</source>
        <translation>ベンダ(&amp;E)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Category:</source>
        <translation>カテゴリ(&amp;C)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RTC t&amp;ype:</source>
        <translation>RTCタイプ(&amp;Y)：</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+8"/>
        <location line="+5"/>
        <source>(not set)</source>
        <translation>（未設定）</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Behaviour</source>
        <translation>動作</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Component &amp;type:</source>
        <translation>コンポーネント型(&amp;T)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Activity type:</source>
        <translation>アクティビティ型(&amp;A)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Max instances:</source>
        <translation>最大インスタンス数(&amp;M)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Execution Context</source>
        <translation>実行コンテキスト</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;xecution type:</source>
        <translation>実行型(&amp;X)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Execution &amp;rate (Hz):</source>
        <translation>実行周期 (Hz)(&amp;R)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Language</source>
        <translation>言語</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&amp;Generate</source>
        <translation>コード生成(&amp;G)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Generate the component&apos;s code from this profile</source>
        <translation>このプロファイルからコンポーネントのコードを生成します</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Code &amp;Restore...</source>
        <translation>コード復元(&amp;R)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Put back generated files from a backup</source>
        <translation>生成したファイルをバックアップから戻します</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear &amp;Backups</source>
        <translation>バックアップの消去(&amp;B)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete the backups made when generating over existing files</source>
        <translation>既存のファイルに上書き生成したときに作成されたバックアップを削除します</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>&amp;Import...</source>
        <translation>インポート(&amp;I)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace this component by the profile of an RTC.xml or YAML file</source>
        <translation>このコンポーネントを RTC.xml または YAML ファイルのプロファイルで置き換えます</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>E&amp;xport...</source>
        <translation>エクスポート(&amp;X)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write this component&apos;s profile to an XML or YAML file</source>
        <translation>このコンポーネントのプロファイルを XML または YAML ファイルに書き出します</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Import Profile</source>
        <translation>プロファイルのインポート</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Export Profile</source>
        <translation>プロファイルのエクスポート</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Nothing was imported from %1:</source>
        <translation>%1 からは何もインポートされませんでした：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 holds the same component; nothing changed.</source>
        <translation>%1 は同じコンポーネントです。変更はありません。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Imported %1 (Undo puts the previous component back).</source>
        <translation>%1 をインポートしました（元に戻すと以前のコンポーネントに戻ります）。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Nothing was exported:</source>
        <translation>何もエクスポートされませんでした：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Exported to %1.</source>
        <translation>%1 にエクスポートしました。</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Cannot generate while these problems remain:
%1</source>
        <translation>次の問題が残っているため、生成できません：
%1</translation>
    </message>
    <message>
        <location line="+91"/>
        <source>A&amp;bstract:</source>
        <translation>概要(&amp;B)：</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>DataFlow</source>
        <translation>DataFlow</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FSM</source>
        <translation>FSM</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>MultiMode</source>
        <translation>MultiMode</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Component &amp;kind:</source>
        <translation>コンポーネントの種類(&amp;K)：</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Generate for:</source>
        <translation>生成する言語：</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>(unnamed component)</source>
        <translation>（名前のないコンポーネント）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Component id: %1</source>
        <translation>コンポーネントID：%1</translation>
    </message>
</context>
<context>
    <name>Builder::BuildController</name>
    <message>
        <location filename="../../builder/buildcontroller.cpp" line="+37"/>
        <source>&amp;Build</source>
        <translation>ビルド(&amp;B)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel Build</source>
        <translation>ビルドの中止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Build &amp;Settings…</source>
        <translation>ビルド設定(&amp;S)…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Configure and build the generated C++ project with CMake, or check that the Python component loads into a manager</source>
        <translation>生成された C++ プロジェクトを CMake で構成・ビルドするか、Python コンポーネントがマネージャにロードできるか確認します</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stop the running build</source>
        <translation>実行中のビルドを停止します</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The SDK prefix (CMAKE_PREFIX_PATH) and the build type</source>
        <translation>SDK プレフィックス (CMAKE_PREFIX_PATH) とビルドタイプ</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Nothing to build: generate the component&apos;s project first.</source>
        <translation>ビルドするものがありません。先にコンポーネントのプロジェクトを生成してください。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Building %1…</source>
        <translation>%1 をビルド中…</translation>
    </message>
</context>
<context>
    <name>Builder::BuildOutputPanel</name>
    <message>
        <location filename="../../builder/buildoutputpanel.cpp" line="+41"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the build</source>
        <translation>ビルドを停止します</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Build output</source>
        <translation>ビルド出力</translation>
    </message>
</context>
<context>
    <name>Builder::BuildSettingsDialog</name>
    <message>
        <location filename="../../builder/buildsettingsdialog.cpp" line="+22"/>
        <source>Build Settings</source>
        <translation>ビルド設定</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Browse…</source>
        <translation>参照(&amp;B)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Default</source>
        <translation>デフォルト(&amp;D)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>(none: CMake searches the system)</source>
        <translation>（なし：CMake がシステムを検索します）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Passed to CMake as CMAKE_PREFIX_PATH, so that find_package(OpenRTM) finds this SDK</source>
        <translation>find_package(OpenRTM) がこの SDK を見つけられるよう、CMAKE_PREFIX_PATH として CMake に渡されます</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SDK &amp;prefix:</source>
        <translation>SDK プレフィックス(&amp;P)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Release</source>
        <translation>リリース</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Debug</source>
        <translation>デバッグ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Build &amp;type:</source>
        <translation>ビルドタイプ(&amp;T)：</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>SDK Prefix</source>
        <translation>SDK プレフィックス</translation>
    </message>
</context>
<context>
    <name>Builder::CodeRestoreDialog</name>
    <message>
        <location filename="../../builder/coderestoredialog.cpp" line="+23"/>
        <source>Code Restore</source>
        <translation>コード復元</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Backups in %1. Restoring a set swaps its files with the current ones, so the current files become a backup in turn.</source>
        <translation>%1 内のバックアップです。セットを復元するとそのファイルと現在のファイルが入れ替わり、今度は現在のファイルがバックアップになります。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Files of the selected backup:</source>
        <translation>選択したバックアップのファイル：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Restore</source>
        <translation>復元(&amp;R)</translation>
    </message>
</context>
<context>
    <name>Builder::ComponentEditor</name>
    <message>
        <location filename="../../builder/componenteditor.cpp" line="+37"/>
        <source>Builder</source>
        <translation>ビルダ</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Basic</source>
        <translation>基本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Activity</source>
        <translation>アクティビティ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data Ports</source>
        <translation>データポート</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Service Ports</source>
        <translation>サービスポート</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration</source>
        <translation>コンフィギュレーション</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Documentation</source>
        <translation>ドキュメント</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Language/Environment</source>
        <translation>言語・環境</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTC.xml</source>
        <translation>RTC.xml</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>The interface type &apos;%1&apos; is not declared in any parsed IDL file.</source>
        <translation>インターフェース型「%1」は、読み込んだどの IDL ファイルにも宣言されていません。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>interface %1 of %2</source>
        <translation>%2 のインターフェース %1</translation>
    </message>
</context>
<context>
    <name>Builder::ComponentModel</name>
    <message>
        <location filename="../../builder/componentmodel.cpp" line="+162"/>
        <source>component name</source>
        <translation>コンポーネント名</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>description</source>
        <translation>説明</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>version</source>
        <translation>バージョン</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>vendor</source>
        <translation>ベンダ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>category</source>
        <translation>カテゴリ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>component type</source>
        <translation>コンポーネント型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>activity type</source>
        <translation>アクティビティ型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>max instances</source>
        <translation>最大インスタンス数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>execution type</source>
        <translation>実行型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>component kind</source>
        <translation>コンポーネントの種類</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>abstract</source>
        <translation>概要</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RTC type</source>
        <translation>RTCタイプ</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>execution rate</source>
        <translation>実行周期</translation>
    </message>
    <message>
        <location line="+137"/>
        <source>data port</source>
        <translation>データポート</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>service port</source>
        <translation>サービスポート</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>configuration parameter</source>
        <translation>コンフィギュレーションパラメータ</translation>
    </message>
</context>
<context>
    <name>Builder::ComponentPreview</name>
    <message>
        <location filename="../../builder/componentpreview.cpp" line="+36"/>
        <source>no events</source>
        <translation>イベントなし</translation>
    </message>
    <message>
        <location line="+204"/>
        <source>(unnamed)</source>
        <translation>（名前なし）</translation>
    </message>
</context>
<context>
    <name>Builder::ComponentRules</name>
    <message>
        <location filename="../../builder/componentrules.cpp" line="+40"/>
        <location line="+217"/>
        <source>interface %1 of %2</source>
        <translation>%2 のインターフェース %1</translation>
    </message>
    <message>
        <location line="-214"/>
        <source>configuration parameter %1</source>
        <translation>コンフィギュレーションパラメータ %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+209"/>
        <source>%1 #%2</source>
        <translation>%1 #%2</translation>
    </message>
    <message>
        <location line="-188"/>
        <source>The port name &apos;%1&apos; is already used by %2.</source>
        <translation>ポート名「%1」は既に %2 で使われています。</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>The variable name &apos;%1&apos; is already used by %2.</source>
        <translation>変数名「%1」は既に %2 で使われています。</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>The step of a %1 must be a number of 0 or more.</source>
        <translation>%1 のステップは 0 以上の数値でなければなりません。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A radio widget needs an enumeration constraint such as (a,b,c).</source>
        <translation>radio ウィジェットには (a,b,c) のような列挙の制約が必要です。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The parameter name &apos;%1&apos; is already used by parameter #%2.</source>
        <translation>パラメータ名「%1」は既にパラメータ #%2 で使われています。</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>The interface name &apos;%1&apos; is already used in this port.</source>
        <translation>インターフェース名「%1」はこのポートで既に使われています。</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>A composite component (category &apos;%1&apos;) may have no ports.</source>
        <translation>複合コンポーネント（カテゴリ「%1」）はポートを持つことができません。</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>component</source>
        <translation>コンポーネント</translation>
    </message>
</context>
<context>
    <name>Builder::ConfigurationPage</name>
    <message>
        <location filename="../../builder/configurationpage.cpp" line="+48"/>
        <location line="+114"/>
        <source>Constraint</source>
        <translation>制約</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>Constraint syntax: %1</source>
        <translation>制約の構文：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Widget</source>
        <translation>ウィジェット</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Step</source>
        <translation>ステップ</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Type</source>
        <translation>型</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+40"/>
        <source>Default value</source>
        <translation>デフォルト値</translation>
    </message>
    <message>
        <location line="-38"/>
        <source>Variable name</source>
        <translation>変数名</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+38"/>
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Configuration parameters</source>
        <translation>コンフィギュレーションパラメータ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Documentation</source>
        <translation>ドキュメント</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Data name</source>
        <translation>データ名</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Description</source>
        <translation>説明</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Range</source>
        <translation>範囲</translation>
    </message>
</context>
<context>
    <name>Builder::DataPortsPage</name>
    <message>
        <location filename="../../builder/dataportspage.cpp" line="+31"/>
        <source>Data type</source>
        <translation>データ型</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Position</source>
        <translation>表示位置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Variable name</source>
        <translation>変数名</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>InPorts</source>
        <translation>InPort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OutPorts</source>
        <translation>OutPort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EventPorts (FSM)</source>
        <translation>EventPort (FSM)</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>Events of the selected EventPort</source>
        <translation>選択した EventPort のイベント</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Add Event</source>
        <translation>イベントの追加</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove Event</source>
        <translation>イベントの削除</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Port</source>
        <translation>ポート</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>IDL file</source>
        <translation>IDL ファイル</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Documentation</source>
        <translation>ドキュメント</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Description</source>
        <translation>説明</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data type description</source>
        <translation>データ型の説明</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Number of data</source>
        <translation>データ数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Semantics</source>
        <translation>意味</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Occurrence frequency</source>
        <translation>発生頻度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operation frequency</source>
        <translation>処理頻度</translation>
    </message>
</context>
<context>
    <name>Builder::DocumentationPage</name>
    <message>
        <location filename="../../builder/documentationpage.cpp" line="+29"/>
        <source>&amp;Description:</source>
        <translation>説明(&amp;D)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Input and output:</source>
        <translation>入出力(&amp;I)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Algorithm:</source>
        <translation>アルゴリズム(&amp;A)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reference:</source>
        <translation>参考文献(&amp;R)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Creator and contact:</source>
        <translation>作成者・連絡先(&amp;C)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;License:</source>
        <translation>ライセンス(&amp;L)：</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Name &lt;mail@example.org&gt;</source>
        <translation>名前 &lt;mail@example.org&gt;</translation>
    </message>
</context>
<context>
    <name>Builder::EditItemCommand</name>
    <message>
        <location filename="../../builder/itemcommands.cpp" line="+139"/>
        <source>Add interface %1 to %2</source>
        <translation>インターフェース %1 を %2 に追加</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Remove interface %1 from %2</source>
        <translation>インターフェース %1 を %2 から削除</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Change interface %1</source>
        <translation>インターフェース %1 を変更</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Add event %1 to %2</source>
        <translation>イベント %1 を %2 に追加</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Remove event %1 from %2</source>
        <translation>イベント %1 を %2 から削除</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Change event %1</source>
        <translation>イベント %1 を変更</translation>
    </message>
</context>
<context>
    <name>Builder::EventTableModel</name>
    <message>
        <location filename="../../builder/eventtablemodel.cpp" line="+177"/>
        <source>An event needs a name.</source>
        <translation>イベントには名前が必要です。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The event name &apos;%1&apos; is already used by event #%2.</source>
        <translation>イベント名「%1」は既にイベント #%2 で使われています。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>An event needs the state it leaves.</source>
        <translation>イベントには遷移元の状態が必要です。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>An event needs the state it enters.</source>
        <translation>イベントには遷移先の状態が必要です。</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Data type</source>
        <translation>データ型</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Source state</source>
        <translation>遷移元の状態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Target state</source>
        <translation>遷移先の状態</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Condition</source>
        <translation>条件</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Description</source>
        <translation>説明</translation>
    </message>
</context>
<context>
    <name>Builder::FieldRules</name>
    <message>
        <location filename="../../builder/builderfieldrules.cpp" line="+39"/>
        <source>A name is required.</source>
        <translation>名前は必須です。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Only letters A-Z a-z, digits, &apos;_&apos;, &apos;-&apos; and &apos;:&apos; are allowed (found %1).</source>
        <translation>使用できるのは英字 A-Z a-z、数字、&apos;_&apos;、&apos;-&apos;、&apos;:&apos; のみです（%1 が含まれています）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>This field is required.</source>
        <translation>この項目は必須です。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Enter a whole number of 0 or more (0 = unlimited).</source>
        <translation>0 以上の整数を入力してください（0 = 無制限）。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Enter a number of 0 or more.</source>
        <translation>0 以上の数値を入力してください。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;%1&quot; is not one of %2.</source>
        <translation>「%1」は %2 のいずれでもありません。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A variable name is a letter or &apos;_&apos; followed by letters, digits or &apos;_&apos;.</source>
        <translation>変数名は英字または &apos;_&apos; で始まり、英字、数字、&apos;_&apos; が続く必要があります。</translation>
    </message>
</context>
<context>
    <name>Builder::GenerateController</name>
    <message>
        <location filename="../../builder/generatecontroller.cpp" line="+160"/>
        <source>Created</source>
        <translation>作成</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Merged</source>
        <translation>マージ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overwritten</source>
        <translation>上書き</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kept</source>
        <translation>保持</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unchanged</source>
        <translation>変更なし</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Backups made</source>
        <translation>作成したバックアップ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Old backups deleted</source>
        <translation>削除した古いバックアップ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <location line="+55"/>
        <location line="+25"/>
        <location line="+10"/>
        <location line="+4"/>
        <location filename="../../builder/generatedialogprompts.cpp" line="+58"/>
        <source>Generate</source>
        <translation>コード生成</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>No code can be generated for this language.</source>
        <translation>この言語のコードは生成できません。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown language &apos;%1&apos; (C++, Python or Java)</source>
        <translation>不明な言語「%1」（C++、Python、Java のいずれかを指定してください）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The code could not be generated.</source>
        <translation>コードを生成できませんでした。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Nothing was written to %1.</source>
        <translation>%1 には何も書き込まれませんでした。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Generated into %1.</source>
        <translation>%1 に生成しました。</translation>
    </message>
    <message>
        <location line="+28"/>
        <location line="+9"/>
        <location line="+7"/>
        <source>Code Restore</source>
        <translation>コード復元</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+34"/>
        <source>%1 has no backups.</source>
        <translation>%1 にはバックアップがありません。</translation>
    </message>
    <message>
        <location line="-25"/>
        <source>The backup of %1 was not restored.</source>
        <translation>%1 のバックアップは復元されませんでした。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Restored the files of %1; the replaced files are now that backup, so restoring it again undoes this.</source>
        <translation>%1 のファイルを復元しました。置き換えられたファイルが新たにそのバックアップとなったため、もう一度復元するとこの操作を取り消せます。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Restored</source>
        <translation>復元</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+10"/>
        <source>Clear Backups</source>
        <translation>バックアップの消去</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>%1 backup files could not be deleted</source>
        <translation>%1 個のバックアップファイルを削除できませんでした</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Deleted %1 backup files.</source>
        <translation>%1 個のバックアップファイルを削除しました。</translation>
    </message>
</context>
<context>
    <name>Builder::GenerateOptionsDialog</name>
    <message>
        <location filename="../../builder/generateoptionsdialog.cpp" line="+21"/>
        <source>Also generate a &amp;test component</source>
        <translation>テストコンポーネントも生成する(&amp;T)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Generate</source>
        <translation>コード生成</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Browse…</source>
        <translation>参照(&amp;B)…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Output folder:</source>
        <translation>出力フォルダ(&amp;O)：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Merged and overwritten files are backed up as &lt;file&gt;YYYYMMDDHHMMSS; older backups beyond this number are deleted.</source>
        <translation>マージまたは上書きされたファイルは &lt;file&gt;YYYYMMDDHHMMSS としてバックアップされ、この数を超えた古いバックアップは削除されます。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Backups kept per file:</source>
        <translation>ファイルごとのバックアップ保持数(&amp;B)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writes test/: a project of the component &lt;N&gt;Test (in C++, or in Python when Python is the only language), whose ports mirror this component&apos;s, to exercise it by connecting the two.</source>
        <translation>test/ に、このコンポーネントと対になるポートを持つコンポーネント &lt;N&gt;Test のプロジェクト（C++。言語が Python だけのときは Python）を書き出します。両者を接続して動作を確認できます。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Generate</source>
        <translation>生成(&amp;G)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Output Folder</source>
        <translation>出力フォルダ</translation>
    </message>
</context>
<context>
    <name>Builder::GenerateOutcome</name>
    <message>
        <location filename="../../builder/generateoutcome.cpp" line="+40"/>
        <source>created</source>
        <translation>作成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>merged (generated regions refreshed, your code kept)</source>
        <translation>マージ（生成領域を更新、ユーザーのコードは保持）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>overwritten</source>
        <translation>上書き</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>kept as it was (not regenerated)</source>
        <translation>そのまま保持（再生成なし）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>backup of the previous file</source>
        <translation>以前のファイルのバックアップ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Generated into %1: %2 written, %3 kept, %4 unchanged.</source>
        <translation>%1 に生成しました：書き込み %2、保持 %3、変更なし %4。</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>Generate refused: %n problem(s) to fix first.</source>
        <translation>
            <numerusform>コード生成を中止しました：先に修正が必要な問題が %n 件あります。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>Code generation failed with %n problem(s).</source>
        <translation>
            <numerusform>コード生成に失敗しました（問題 %n 件）。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Builder::IdlSettingsDialog</name>
    <message>
        <location filename="../../builder/idlsettingsdialog.cpp" line="+24"/>
        <source>IDL Folders</source>
        <translation>IDLフォルダ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bundled OpenRTM IDL: %1</source>
        <translation>同梱の OpenRTM IDL：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Add...</source>
        <translation>追加(&amp;A)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Remove</source>
        <translation>削除(&amp;R)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IDL Folder</source>
        <translation>IDLフォルダ</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Your IDL folders (searched after the bundled one):</source>
        <translation>追加のIDLフォルダ（同梱のフォルダの後に検索）：</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop reading the IDL folders and keep the types read before</source>
        <translation>IDL フォルダーの読み込みを中止し、以前に読み込んだ型をそのまま使います</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Reading the IDL folders…</source>
        <translation>IDL フォルダーを読み込んでいます…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Reading %1 (%2 of %3)</source>
        <translation>%1 を読み込んでいます（%3 件中 %2 件目）</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>IDL Folders...</source>
        <translation>IDLフォルダ...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reload Types</source>
        <translation>型を再読み込み</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parse the IDL folders again</source>
        <translation>IDLフォルダを再度解析します</translation>
    </message>
</context>
<context>
    <name>Builder::ItemForm</name>
    <message>
        <location filename="../../builder/itemform.cpp" line="+242"/>
        <source>Change %1 of %2</source>
        <translation>%2 の %1 を変更</translation>
    </message>
</context>
<context>
    <name>Builder::ItemTableModel</name>
    <message>
        <location filename="../../builder/itemtablemodel.cpp" line="+95"/>
        <source>Change %1 of %2</source>
        <translation>%2 の %1 を変更</translation>
    </message>
</context>
<context>
    <name>Builder::KindChoices</name>
    <message>
        <location filename="../../builder/kindchoices.cpp" line="+51"/>
        <source>Choose at least one component kind (DataFlow, FSM or MultiMode).</source>
        <translation>コンポーネントの種類（DataFlow、FSM、MultiMode）を1つ以上選択してください。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&quot;%1&quot; names none of the kinds DataFlow, FiniteStateMachine or MultiMode.</source>
        <translation>「%1」は DataFlow、FiniteStateMachine、MultiMode のいずれの種類にも該当しません。</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Choose at least one language.</source>
        <translation>言語を1つ以上選択してください。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>No code can be generated for %1 (C++, Python or Java).</source>
        <translation>%1 のコードは生成できません（生成できるのは C++、Python、Java です）。</translation>
    </message>
</context>
<context>
    <name>Builder::LanguagePage</name>
    <message>
        <location filename="../../builder/languagepage.cpp" line="+61"/>
        <source>Language</source>
        <translation>言語</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Language:</source>
        <translation>言語(&amp;L)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Target environment</source>
        <translation>対象環境</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Language &amp;version:</source>
        <translation>言語バージョン(&amp;V)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;OS:</source>
        <translation>OS(&amp;O)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OS ve&amp;rsions (comma separated):</source>
        <translation>OSバージョン（カンマ区切り）(&amp;R)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;CPUs (comma separated):</source>
        <translation>CPU（カンマ区切り）(&amp;C)：</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Add Library</source>
        <translation>ライブラリを追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove Library</source>
        <translation>ライブラリを削除</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>library</source>
        <translation>ライブラリ</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Libraries:</source>
        <translation>ライブラリ：</translation>
    </message>
</context>
<context>
    <name>Builder::LibraryTableModel</name>
    <message>
        <location filename="../../builder/librarytablemodel.cpp" line="+114"/>
        <source>Library</source>
        <translation>ライブラリ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Version</source>
        <translation>バージョン</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Other</source>
        <translation>その他</translation>
    </message>
</context>
<context>
    <name>Builder::ListEditor</name>
    <message>
        <location filename="../../builder/listeditor.cpp" line="+83"/>
        <source>Remove</source>
        <translation>削除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Up</source>
        <translation>上へ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Down</source>
        <translation>下へ</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Add</source>
        <translation>追加</translation>
    </message>
</context>
<context>
    <name>Builder::ModuleRun</name>
    <message>
        <location filename="../../builder/modulerun.cpp" line="+37"/>
        <source>no answer within %1 s</source>
        <translation>%1 秒以内に応答がありません</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>manager %1 unreachable (%2)</source>
        <translation>マネージャ %1 は到達不能です（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>manager %1 did not answer within %2 s</source>
        <translation>マネージャ %1 が %2 秒以内に応答しませんでした</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>load_module refused: %1</source>
        <translation>load_module が拒否されました：%1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>create_component failed: %1</source>
        <translation>create_component が失敗しました：%1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Could not run %1 in manager %2: %3</source>
        <translation>マネージャ %2 で %1 を実行できませんでした：%3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; is not a manager address (host:port)</source>
        <translation>「%1」はマネージャのアドレス（host:port）ではありません</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no module file %1</source>
        <translation>モジュールファイル %1 がありません</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>unexpected error</source>
        <translation>予期しないエラー</translation>
    </message>
</context>
<context>
    <name>Builder::PackageController</name>
    <message>
        <location filename="../../builder/packagecontroller.cpp" line="+50"/>
        <source>&amp;Package</source>
        <translation>パッケージ作成(&amp;P)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;ublish…</source>
        <translation>公開(&amp;U)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Make the Debian package (.deb) of the built component</source>
        <translation>ビルドしたコンポーネントの Debian パッケージ（.deb）を作成します</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the package and add it to a component repository</source>
        <translation>パッケージを作成してコンポーネントリポジトリに追加します</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Publish into Repository</source>
        <translation>リポジトリへ公開</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Nothing to package: generate and build the component&apos;s project first.</source>
        <translation>パッケージにするものがありません：先にコンポーネントのプロジェクトを生成してビルドしてください。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nothing to package: build %1 first.</source>
        <translation>パッケージにするものがありません：先に %1 をビルドしてください。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Packaging %1…</source>
        <translation>%1 をパッケージ化しています…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Packaging %1 for %2…</source>
        <translation>%2 向けに %1 をパッケージ化しています…</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Cannot create the folder %1.</source>
        <translation>フォルダ %1 を作成できません。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Packaging failed: %1</source>
        <translation>パッケージ化に失敗しました：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Made %1</source>
        <translation>%1 を作成しました</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Made %1.</source>
        <translation>%1 を作成しました。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot publish %1 into %2: %3</source>
        <translation>%1 を %2 に公開できません：%3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Published %1 into %2.</source>
        <translation>%1 を %2 に公開しました。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
</context>
<context>
    <name>Builder::ProfileChanges</name>
    <message>
        <location filename="../../builder/profilechanges.cpp" line="+22"/>
        <source>(none)</source>
        <translation>（なし）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Basic: %1 %2 → %3</source>
        <translation>基本：%1 %2 → %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Documentation changed</source>
        <translation>ドキュメントが変更されました</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: %2 → %3</source>
        <translation>%1：%2 → %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>on</source>
        <translation>オン</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+1"/>
        <source>off</source>
        <translation>オフ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 changed</source>
        <translation>%1 が変更されました</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 &apos;%2&apos; removed</source>
        <translation>%1「%2」が削除されました</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 &apos;%2&apos; added</source>
        <translation>%1「%2」が追加されました</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 &apos;%2&apos; changed</source>
        <translation>%1「%2」が変更されました</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Order of %1s changed</source>
        <translation>%1 の順序が変更されました</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Component id &apos;%1&apos; → &apos;%2&apos;</source>
        <translation>コンポーネントID「%1」→「%2」</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Data port</source>
        <translation>データポート</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Service port</source>
        <translation>サービスポート</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration parameter</source>
        <translation>コンフィギュレーションパラメータ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Language and environment changed</source>
        <translation>言語・環境が変更されました</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Other content changed (dates, properties, unknown elements)</source>
        <translation>その他の内容が変更されました（日付、プロパティ、不明な要素）</translation>
    </message>
</context>
<context>
    <name>Builder::ProfileTransfer</name>
    <message>
        <location filename="../../builder/profiletransfer.cpp" line="+34"/>
        <source>This file holds a system (RTS Profile), not a component; open it in the System Editor instead.</source>
        <translation>このファイルはコンポーネントではなくシステム（RTSプロファイル）を含んでいます。システムエディタで開いてください。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Import %1</source>
        <translation>%1 をインポート</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>RTC Profile (*.xml *.yaml *.yml);;All files (*)</source>
        <translation>RTCプロファイル (*.xml *.yaml *.yml);;すべてのファイル (*)</translation>
    </message>
</context>
<context>
    <name>Builder::RegenerationDialog</name>
    <message>
        <location filename="../../builder/regenerationdialog.cpp" line="+24"/>
        <source>&amp;Apply to all remaining changed files</source>
        <translation>残りの変更されたファイルすべてに適用(&amp;A)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Generated File Changed</source>
        <translation>生成ファイルが変更されています</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;b&gt;%1&lt;/b&gt; exists and differs from the newly generated file. Lines starting with - are in your file only, + in the new one.</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; は既に存在し、新しく生成されたファイルと異なります。- で始まる行は既存のファイルのみに、+ で始まる行は新しいファイルのみにあります。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 (existing)</source>
        <translation>%1（既存）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 (new)</source>
        <translation>%1（新規）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Keep</source>
        <translation>保持(&amp;K)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Leave your file as it is</source>
        <translation>ファイルをそのまま残します</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Merge</source>
        <translation>マージ(&amp;M)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back your file up, then refresh only its generated regions</source>
        <translation>ファイルをバックアップしてから、生成された領域のみを更新します</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Overwrite</source>
        <translation>上書き(&amp;O)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back your file up, then replace it with the new file</source>
        <translation>ファイルをバックアップしてから、新しいファイルで置き換えます</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>(only line endings differ)</source>
        <translation>（改行コードのみが異なります）</translation>
    </message>
</context>
<context>
    <name>Builder::RtcXmlPage</name>
    <message>
        <location filename="../../builder/rtcxmlpage.cpp" line="+46"/>
        <source>&amp;Apply</source>
        <translation>適用(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;vert</source>
        <translation>破棄(&amp;V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read the XML and show what it changes</source>
        <translation>XMLを読み込み、変更内容を表示します</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the component&apos;s XML again, dropping your edits</source>
        <translation>編集内容を破棄し、コンポーネントのXMLを再表示します</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Confirm</source>
        <translation>確定(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ca&amp;ncel</source>
        <translation>キャンセル(&amp;N)</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>The XML has errors; the component is unchanged.</source>
        <translation>XMLにエラーがあります。コンポーネントは変更されていません。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No changes.</source>
        <translation>変更はありません。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Applying changes the component:
• %1</source>
        <translation>適用するとコンポーネントは次のように変更されます：
• %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Confirm to take the changes.</source>
        <translation>変更を反映するには確定してください。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Applied.</source>
        <translation>適用しました。</translation>
    </message>
</context>
<context>
    <name>Builder::RunController</name>
    <message>
        <location filename="../../builder/runcontroller.cpp" line="+39"/>
        <source>&amp;Run in Manager…</source>
        <translation>マネージャで実行(&amp;R)…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Load the built module into a running manager and create the component</source>
        <translation>ビルドしたモジュールを実行中のマネージャにロードし、コンポーネントを生成します</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>Nothing to run: generate and build the component first.</source>
        <translation>実行するものがありません。先にコンポーネントのコード生成とビルドを行ってください。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nothing to run: %1 was not built yet.</source>
        <translation>実行するものがありません。%1 はまだビルドされていません。</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>manager %1</source>
        <translation>マネージャ %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Created %1 in manager %2.</source>
        <translation>マネージャ %2 で %1 を生成しました。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 was loaded already: the manager keeps the code it loaded first.</source>
        <translation>%1 は既にロードされています。マネージャは最初にロードしたコードを使い続けます。</translation>
    </message>
</context>
<context>
    <name>Builder::RunManagerDialog</name>
    <message>
        <location filename="../../builder/runmanagerdialog.cpp" line="+22"/>
        <source>Run in Manager</source>
        <translation>マネージャで実行</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>host:port of a running manager (rtmanager or rtcd), port 2810 when left out</source>
        <translation>実行中のマネージャ（rtmanager または rtcd）の host:port（ポートを省略した場合は 2810）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Run</source>
        <translation>実行(&amp;R)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Manager:</source>
        <translation>マネージャ(&amp;M)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module:</source>
        <translation>モジュール：</translation>
    </message>
</context>
<context>
    <name>Builder::ServicePortTreeModel</name>
    <message>
        <location filename="../../builder/serviceporttreemodel.cpp" line="+144"/>
        <source>Port / interface</source>
        <translation>ポート / インターフェース</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Position / direction and type</source>
        <translation>表示位置 / 方向と型</translation>
    </message>
</context>
<context>
    <name>Builder::ServicePortsPage</name>
    <message>
        <location filename="../../builder/serviceportspage.cpp" line="+94"/>
        <source>Add Port</source>
        <translation>ポートを追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add Interface</source>
        <translation>インターフェースを追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>削除</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&lt;b&gt;Service ports&lt;/b&gt;</source>
        <translation>&lt;b&gt;サービスポート&lt;/b&gt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Select a service port or an interface.</source>
        <translation>サービスポートまたはインターフェースを選択してください。</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Service port</source>
        <translation>サービスポート</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Port name</source>
        <translation>ポート名</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Position</source>
        <translation>表示位置</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+41"/>
        <source>Documentation</source>
        <translation>ドキュメント</translation>
    </message>
    <message>
        <location line="-39"/>
        <location line="+46"/>
        <source>Description</source>
        <translation>説明</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Interface description</source>
        <translation>インターフェースの説明</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Interface</source>
        <translation>インターフェース</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interface name</source>
        <translation>インターフェース名</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Instance name</source>
        <translation>インスタンス名</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Variable name</source>
        <translation>変数名</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Interface type</source>
        <translation>インターフェース型</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>IDL file</source>
        <translation>IDLファイル</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Argument</source>
        <translation>引数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return value</source>
        <translation>戻り値</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exception</source>
        <translation>例外</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Precondition</source>
        <translation>事前条件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Postcondition</source>
        <translation>事後条件</translation>
    </message>
</context>
<context>
    <name>Builder::SourceViewer</name>
    <message>
        <location filename="../../builder/sourceviewer.cpp" line="+50"/>
        <source>Open Externally</source>
        <translation>外部エディタで開く</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open the file in the desktop&apos;s editor</source>
        <translation>デスクトップのエディタでファイルを開きます</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>閉じる</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>%1, line %2</source>
        <translation>%1、%2 行目</translation>
    </message>
</context>
<context>
    <name>ConnectCommand</name>
    <message>
        <location filename="../../systemeditor/connectorcommands.cpp" line="+87"/>
        <location line="+11"/>
        <source>Connect %1</source>
        <translation>%1 を接続</translation>
    </message>
</context>
<context>
    <name>ConnectionRules</name>
    <message>
        <location filename="../../systemeditor/connectionrules.cpp" line="+36"/>
        <location line="+3"/>
        <source>Port %1 of %2 does not exist.</source>
        <translation>%2 のポート %1 は存在しません。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Ports of the same component cannot be connected.</source>
        <translation>同じコンポーネントのポート同士は接続できません。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A data port cannot be connected to a service port.</source>
        <translation>データポートとサービスポートは接続できません。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Two InPorts cannot be connected; connect an OutPort to an InPort.</source>
        <translation>InPort 同士は接続できません。OutPort と InPort を接続してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Two OutPorts cannot be connected; connect an OutPort to an InPort.</source>
        <translation>OutPort 同士は接続できません。OutPort と InPort を接続してください。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The data types differ: %1 and %2.</source>
        <translation>データ型が異なります：%1 と %2。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>No interface of %1 pairs with one of %2 (same instance name, one provided and one required).</source>
        <translation>%1 のインターフェースに %2 のインターフェースと対になるものがありません（インスタンス名が同じで、一方が提供、他方が要求であることが必要です）。</translation>
    </message>
</context>
<context>
    <name>ConnectorSettings</name>
    <message>
        <location filename="../../systemeditor/connectorsettings.cpp" line="+145"/>
        <source>OutPort → InPort (the OutPort connects)</source>
        <translation>OutPort → InPort（OutPort 側から接続）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>InPort → OutPort (the InPort connects)</source>
        <translation>InPort → OutPort（InPort 側から接続）</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>The connector name is empty.</source>
        <translation>コネクタ名が空です。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The connector name is longer than %1 characters.</source>
        <translation>コネクタ名が %1 文字を超えています。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose an interface type.</source>
        <translation>インターフェース型を選択してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose a dataflow type (push, pull or duplex).</source>
        <translation>データフロー型（push、pull、duplex）を選択してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose a subscription type (flush, new or periodic).</source>
        <translation>サブスクリプション型（flush、new、periodic）を選択してください。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The push rate must be a number greater than 0.</source>
        <translation>プッシュ周期には 0 より大きい数値を指定してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose a push policy (all, fifo, skip or new).</source>
        <translation>プッシュポリシー（all、fifo、skip、new）を選択してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The skip count must be an integer of 0 or more.</source>
        <translation>スキップ数には 0 以上の整数を指定してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unknown timestamp policy &quot;%1&quot;.</source>
        <translation>タイムスタンプポリシー「%1」は不明です。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The %1 buffer length must be an integer greater than 0.</source>
        <translation>%1 のバッファ長には 0 より大きい整数を指定してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unknown %1 buffer full policy &quot;%2&quot;.</source>
        <translation>%1 のバッファフル時ポリシー「%2」は不明です。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unknown %1 buffer empty policy &quot;%2&quot;.</source>
        <translation>%1 のバッファエンプティ時ポリシー「%2」は不明です。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 buffer write timeout must be a number of 0 or more.</source>
        <translation>%1 のバッファ書き込みタイムアウトには 0 以上の数値を指定してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 buffer read timeout must be a number of 0 or more.</source>
        <translation>%1 のバッファ読み出しタイムアウトには 0 以上の数値を指定してください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>OutPort</source>
        <translation>OutPort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>InPort</source>
        <translation>InPort</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A property has no name.</source>
        <translation>名前のないプロパティがあります。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The property &quot;%1&quot; is listed twice.</source>
        <translation>プロパティ「%1」が重複しています。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The property &quot;%1&quot; is set by a field of this dialog.</source>
        <translation>プロパティ「%1」はこのダイアログの項目で設定されます。</translation>
    </message>
</context>
<context>
    <name>CreateCompositeCommand</name>
    <message>
        <location filename="../../systemeditor/compositecommands.cpp" line="+107"/>
        <source>Create composite %1</source>
        <translation>複合コンポーネント %1 を作成</translation>
    </message>
</context>
<context>
    <name>DecomposeCommand</name>
    <message>
        <location line="+7"/>
        <source>Decompose %1</source>
        <translation>%1 を分解</translation>
    </message>
</context>
<context>
    <name>Deploy::ComponentMapper</name>
    <message>
        <location filename="../../corba/deployment/componentmapper.cpp" line="+51"/>
        <source>%1: another component is named %2 too (%3); one instance name can stand for one component only</source>
        <translation>%1：別のコンポーネントも %2 という名前です（%3）。1 つのインスタンス名が表せるコンポーネントは 1 つだけです</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>no live component named %1</source>
        <translation>稼働中のコンポーネント %1 が見つかりません</translation>
    </message>
    <message>
        <location line="+126"/>
        <source>%1 is a %2, the system wants a %3</source>
        <translation>%1 は %2 ですが、システムが求めているのは %3 です</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1; no manager to create it (give one with -m)</source>
        <translation>%1。生成するマネージャがありません（-m で指定してください）</translation>
    </message>
</context>
<context>
    <name>Deploy::DeployPlan</name>
    <message>
        <location filename="../../corba/deployment/deployer.cpp" line="+103"/>
        <source>%1 on %2: not loadable there and no repository given</source>
        <translation>%2 の %1：そこではロードできず、リポジトリも指定されていません</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 on %2: not loadable there and no package of %3 fits it (%4)</source>
        <translation>%2 の %1：そこではロードできず、%3 にも合うパッケージがありません（%4）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>architecture unknown</source>
        <translation>アーキテクチャ不明</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>node %1: %2</source>
        <translation>ノード %1：%2</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>deploy</source>
        <comment>what the plan check is about</comment>
        <translation>デプロイ</translation>
    </message>
    <message>
        <location line="+75"/>
        <source>%1 %2 on %3</source>
        <comment>package, version on node</comment>
        <translation>%3 の %1 %2</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>repository %1: %2</source>
        <translation>リポジトリ %1：%2</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>install %1 %2 on %3 (%4)</source>
        <translation>%3 に %1 %2 をインストール（%4）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>problem %1</source>
        <translation>問題：%1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>%1 on %2</source>
        <comment>package on node</comment>
        <translation>%2 の %1</translation>
    </message>
</context>
<context>
    <name>Deploy::DeployReport</name>
    <message>
        <location filename="../../corba/deployment/deployreport.cpp" line="+125"/>
        <source>failed: %1</source>
        <translation>失敗：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cancelled</source>
        <translation>キャンセルされました</translation>
    </message>
</context>
<context>
    <name>Deploy::DeployStep</name>
    <message>
        <location line="-115"/>
        <source>find</source>
        <comment>step action</comment>
        <translation>検索</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>create</source>
        <comment>step action</comment>
        <translation>生成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connect</source>
        <comment>step action</comment>
        <translation>接続</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disconnect</source>
        <comment>step action</comment>
        <translation>切断</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configure</source>
        <comment>step action</comment>
        <translation>設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate</source>
        <comment>step action</comment>
        <translation>周期設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>install</source>
        <comment>step action</comment>
        <translation>インストール</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uninstall</source>
        <comment>step action</comment>
        <translation>アンインストール</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exit</source>
        <comment>step action</comment>
        <translation>終了</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>plan</source>
        <comment>step action</comment>
        <translation>計画</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>activate</source>
        <comment>step action</comment>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deactivate</source>
        <comment>step action</comment>
        <translation>非アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>start</source>
        <comment>step action</comment>
        <translation>開始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stop</source>
        <comment>step action</comment>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wait</source>
        <comment>step action</comment>
        <translation>待機</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancel</source>
        <comment>step action</comment>
        <translation>中止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node back</source>
        <comment>step action</comment>
        <translation>ノード復帰</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node lost</source>
        <comment>step action</comment>
        <translation>ノード喪失</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replan</source>
        <comment>step action</comment>
        <translation>再計画</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>list</source>
        <comment>step action</comment>
        <translation>一覧取得</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>save</source>
        <comment>step action</comment>
        <translation>保存</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>planned</source>
        <comment>step status</comment>
        <translation>予定</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>running</source>
        <comment>step status</comment>
        <translation>実行中</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>done</source>
        <comment>step status</comment>
        <translation>完了</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>skipped</source>
        <comment>step status</comment>
        <translation>スキップ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>failed</source>
        <comment>step status</comment>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rolled back</source>
        <comment>step status</comment>
        <translation>ロールバック済み</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 %2</source>
        <comment>step: action, subject</comment>
        <translation>%2 の%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 %2: %3</source>
        <comment>step: action, subject, message</comment>
        <translation>%2 の%1：%3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2</source>
        <comment>step line: status, then the step&apos;s summary</comment>
        <translation>[%1] %2</translation>
    </message>
</context>
<context>
    <name>Deploy::DriftItem</name>
    <message>
        <location filename="../../corba/deployment/drift.cpp" line="+128"/>
        <source>missing component</source>
        <translation>不足しているコンポーネント</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>missing port</source>
        <translation>不足しているポート</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>missing connector</source>
        <translation>不足しているコネクタ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>extra connector</source>
        <translation>余分なコネクタ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>configuration</source>
        <translation>コンフィギュレーション</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>active set</source>
        <translation>アクティブなセット</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>state</source>
        <translation>状態</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unreachable</source>
        <translation>到達不能</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2: saved &apos;%3&apos;, live &apos;%4&apos;</source>
        <translation>%1 %2：保存値「%3」、稼働中「%4」</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2: saved &apos;%3&apos;</source>
        <translation>%1 %2：保存値「%3」</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2: live &apos;%3&apos;</source>
        <translation>%1 %2：稼働中「%3」</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2</source>
        <comment>drift: kind, subject</comment>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>Deploy::LocalRuntime</name>
    <message>
        <location filename="../../corba/deployment/localruntime.cpp" line="+275"/>
        <source>omniNames is not installed (Debian package omniorb-nameserver)</source>
        <translation>omniNames がインストールされていません（Debian パッケージ omniorb-nameserver）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: no rtmanager program there</source>
        <translation>%1: そこに rtmanager プログラムがありません</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: cannot create the folder</source>
        <translation>%1: フォルダーを作成できません</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no free port from 2809 on</source>
        <translation>2809 以降に空きポートがありません</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cannot prepare TLS: %1</source>
        <translation>TLS を準備できません: %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>omniNames did not start on port %1: %2</source>
        <translation>omniNames がポート %1 で起動しませんでした：%2</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>rtmanager did not start on port %1: %2</source>
        <translation>rtmanager がポート %1 で起動しませんでした：%2</translation>
    </message>
</context>
<context>
    <name>Deploy::RestorePlan</name>
    <message>
        <location filename="../../corba/deployment/restoreplan.cpp" line="+65"/>
        <source>problem %1</source>
        <translation>問題：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>connect %1 %2 -&gt; %3 (%4)</source>
        <translation>コネクタ %1 を接続：%2 -&gt; %3（%4）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>component %1 create (%2): %3</source>
        <translation>コンポーネント %1 を生成（%2）：%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>component %1 create (%2)</source>
        <translation>コンポーネント %1 を生成（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>component %1 existing at %2: %3</source>
        <translation>コンポーネント %1 は既存（%2）：%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>component %1 existing at %2</source>
        <translation>コンポーネント %1 は既存（%2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>component %1 missing: %2</source>
        <translation>コンポーネント %1 は不足：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>component %1 missing</source>
        <translation>コンポーネント %1 は不足</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 [optional]</source>
        <comment>a plan line of an optional component</comment>
        <translation>%1［任意］</translation>
    </message>
</context>
<context>
    <name>Deploy::Restorer</name>
    <message>
        <location filename="../../corba/deployment/restorer.cpp" line="+99"/>
        <source>no manager given</source>
        <translation>マネージャが指定されていません</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 by %2</source>
        <comment>created: create argument, manager</comment>
        <translation>%1（%2 で生成）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>not selected</source>
        <translation>未選択</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 or %2 is not there</source>
        <translation>%1 または %2 がありません</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no port %1</source>
        <translation>ポート %1 がありません</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>already connected</source>
        <translation>接続済み</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 -&gt; %2 (replaced a broken connector)</source>
        <translation>%1 -&gt; %2（壊れたコネクタを置き換えました）</translation>
    </message>
    <message>
        <location line="+131"/>
        <source>undone</source>
        <translation>取り消し済み</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>undo failed: %1</source>
        <translation>取り消しに失敗しました：%1</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1 is not there</source>
        <translation>%1 がありません</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>%1: no port named &apos;%2&apos;</source>
        <translation>%1：「%2」という名前のポートはありません</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+12"/>
        <source>not connected</source>
        <translation>未接続</translation>
    </message>
</context>
<context>
    <name>Deploy::SequenceRunner</name>
    <message>
        <location filename="../../corba/deployment/sequencerunner.cpp" line="+297"/>
        <source>%1 ms from the start</source>
        <translation>開始から %1 ms</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>preceding %1 is not there</source>
        <translation>先行する %1 がありません</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>after %1</source>
        <translation>%1 の後</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>preceding %1 is not in the plan</source>
        <translation>先行する %1 は計画にありません</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>after %1 was sent</source>
        <translation>%1 の送信後</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 did not activate within %2 ms of the start</source>
        <translation>%1 は開始から %2 ms 以内にアクティブになりませんでした</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 did not deactivate within %2 ms of the start</source>
        <translation>%1 は開始から %2 ms 以内に非アクティブになりませんでした</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 did not start within %2 ms of the start</source>
        <translation>%1 は開始から %2 ms 以内に開始しませんでした</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 did not stop within %2 ms of the start</source>
        <translation>%1 は開始から %2 ms 以内に停止しませんでした</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>plan</source>
        <comment>the start or stop plan, cancelled</comment>
        <translation>計画</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2</source>
        <comment>instance: reason</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>not selected</source>
        <translation>未選択</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is not there</source>
        <translation>%1 がありません</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>already done</source>
        <translation>実行済み</translation>
    </message>
</context>
<context>
    <name>Deploy::SystemHealer</name>
    <message>
        <location filename="../../corba/deployment/healer.cpp" line="+84"/>
        <source>nothing moved back</source>
        <translation>何も戻していません</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>it ran nothing of the system</source>
        <translation>システムのものは何も動かしていませんでした</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it ran %1</source>
        <translation>%1 を動かしていました</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>no node answers</source>
        <translation>応答するノードがありません</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>no plan on %1: %2</source>
        <translation>%1 では計画が立ちません：%2</translation>
    </message>
</context>
<context>
    <name>DisconnectCommand</name>
    <message>
        <location filename="../../systemeditor/connectorcommands.cpp" line="+34"/>
        <source>Disconnect %1</source>
        <translation>%1 を切断</translation>
    </message>
</context>
<context>
    <name>EditConnectorCommand</name>
    <message>
        <location line="+29"/>
        <location line="+12"/>
        <source>Edit connector %1</source>
        <translation>コネクタ %1 を編集</translation>
    </message>
</context>
<context>
    <name>EditSystemInfoCommand</name>
    <message>
        <location filename="../../app/rtscommands.cpp" line="+81"/>
        <source>Change %1</source>
        <translation>%1 を変更</translation>
    </message>
</context>
<context>
    <name>InsertItemCommand</name>
    <message>
        <location filename="../../builder/itemcommands.cpp" line="-181"/>
        <source>Add %1</source>
        <translation>%1 を追加</translation>
    </message>
</context>
<context>
    <name>MoveComponentsCommand</name>
    <message>
        <location filename="../../systemeditor/instancecommands.cpp" line="+101"/>
        <source>Move</source>
        <translation>移動</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>Align</source>
        <translation>整列</translation>
    </message>
</context>
<context>
    <name>MoveItemCommand</name>
    <message>
        <location filename="../../builder/itemcommands.cpp" line="+46"/>
        <source>Move %1 %2</source>
        <translation>%1 %2 を移動</translation>
    </message>
</context>
<context>
    <name>PasteComponentsCommand</name>
    <message numerus="yes">
        <location filename="../../systemeditor/pastecommand.cpp" line="+191"/>
        <source>Paste %n components</source>
        <translation>
            <numerusform>%n 個のコンポーネントを貼り付け</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PinComponentCommand</name>
    <message>
        <location filename="../../systemeditor/plan/pincommand.cpp" line="+19"/>
        <source>Free %1</source>
        <translation>%1 の固定を解除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pin %1 to %2</source>
        <translation>%1 を %2 に固定</translation>
    </message>
</context>
<context>
    <name>Planner</name>
    <message>
        <location filename="../../planner/matcher.cpp" line="+14"/>
        <source>unknown</source>
        <translation>不明</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>OS %1</source>
        <translation>OS %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>OS version %1</source>
        <translation>OS バージョン %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>architecture %1</source>
        <translation>アーキテクチャ %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>device %1</source>
        <translation>デバイス %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no devices listed</source>
        <translation>デバイスの記載なし</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>node.%1 = %2</source>
        <translation>node.%1 = %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>pinned to %1</source>
        <translation>%1 に固定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the name %1</source>
        <translation>名前 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CPU share %1</source>
        <translation>CPU 割り当て %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 free</source>
        <translation>%1 空き</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>language %1</source>
        <translation>言語 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>type %1 loadable or installable</source>
        <translation>型 %1 がロードまたはインストール可能</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no such type, no package for its architecture (%1) and SDK</source>
        <translation>その型はなく、アーキテクチャ (%1) と SDK に合うパッケージもありません</translation>
    </message>
    <message>
        <location filename="../../planner/planner.cpp" line="+156"/>
        <source>same process (%1) as %2</source>
        <translation>%2 と同じプロセス (%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> not met</source>
        <translation> を満たしません</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>CPU shares together within the free CPUs of %1</source>
        <translation>%1 の空き CPU に収まる CPU 割り当ての合計</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 CPUs free</source>
        <translation>空き CPU %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>a node to run on</source>
        <translation>実行するノード</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no nodes given</source>
        <translation>ノードが指定されていません</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>a plan within %1 ms</source>
        <translation>%1 ms 以内の配置計画</translation>
    </message>
    <message>
        <location filename="../../planner/requirements.cpp" line="+71"/>
        <source>%1: %2 &apos;%3&apos; is not a number of CPUs; ignored</source>
        <translation>%1: %2 の &apos;%3&apos; は CPU 数ではないため無視しました</translation>
    </message>
    <message>
        <location line="+104"/>
        <source>no RTC profile of %1: only the components&apos; own deploy.* properties are required</source>
        <translation>%1 の RTC プロファイルがありません: コンポーネント自身の deploy.* プロパティだけを要件とします</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../../builder/generatedialogprompts.cpp" line="-12"/>
        <source>Clear Backups</source>
        <translation>バックアップの削除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete all %1 backup files of generated code in %2? They cannot be restored afterwards.</source>
        <translation>%2 にある生成コードのバックアップファイル %1 個をすべて削除しますか？削除後は元に戻せません。</translation>
    </message>
</context>
<context>
    <name>RemoveComponentsCommand</name>
    <message>
        <location filename="../../systemeditor/instancecommands.cpp" line="-95"/>
        <source>Delete %1</source>
        <translation>%1 を削除</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Delete %n components</source>
        <translation>
            <numerusform>%n 個のコンポーネントを削除</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RemoveItemCommand</name>
    <message>
        <location filename="../../builder/itemcommands.cpp" line="-23"/>
        <source>Remove %1 %2</source>
        <translation>%1 %2 を削除</translation>
    </message>
</context>
<context>
    <name>RenameComponentCommand</name>
    <message>
        <location filename="../../systemeditor/instancecommands.cpp" line="+147"/>
        <source>Rename %1 to %2</source>
        <translation>%1 の名前を %2 に変更</translation>
    </message>
</context>
<context>
    <name>ReplaceProfileCommand</name>
    <message>
        <location filename="../../builder/componentcommands.cpp" line="+121"/>
        <source>Edit RTC.xml</source>
        <translation>RTC.xml を編集</translation>
    </message>
</context>
<context>
    <name>ResizeComponentCommand</name>
    <message>
        <location filename="../../systemeditor/instancecommands.cpp" line="-39"/>
        <source>Resize %1</source>
        <translation>%1 のサイズを変更</translation>
    </message>
</context>
<context>
    <name>ServiceConnectorSettings</name>
    <message>
        <location filename="../../systemeditor/serviceconnectorsettings.cpp" line="+123"/>
        <source>The name must have 1 to %1 characters.</source>
        <translation>名前は 1～%1 文字で指定してください。</translation>
    </message>
</context>
<context>
    <name>SetActionCommand</name>
    <message>
        <location filename="../../builder/componentcommands.cpp" line="-39"/>
        <source>Change %1</source>
        <translation>%1 を変更</translation>
    </message>
</context>
<context>
    <name>SetBasicFieldCommand</name>
    <message>
        <location line="-63"/>
        <source>Change %1</source>
        <translation>%1 を変更</translation>
    </message>
</context>
<context>
    <name>SetBendPointsCommand</name>
    <message>
        <location filename="../../systemeditor/connectorcommands.cpp" line="+58"/>
        <source>Edit bend points</source>
        <translation>折れ点を編集</translation>
    </message>
</context>
<context>
    <name>SetComponentDocCommand</name>
    <message>
        <location filename="../../builder/componentcommands.cpp" line="+76"/>
        <source>Change documentation</source>
        <translation>ドキュメントを変更</translation>
    </message>
</context>
<context>
    <name>SetConfigurationSetsCommand</name>
    <message>
        <location filename="../../systemeditor/instancecommands.cpp" line="+98"/>
        <source>Edit configuration of %1</source>
        <translation>%1 のコンフィギュレーションを編集</translation>
    </message>
</context>
<context>
    <name>SetConfigurationValueCommand</name>
    <message>
        <location filename="../../systemeditor/configurationcommands.cpp" line="+60"/>
        <source>Set %1 of %2 to &quot;%3&quot;</source>
        <translation>%2 の %1 を「%3」に設定</translation>
    </message>
</context>
<context>
    <name>SetDirectionCommand</name>
    <message>
        <location filename="../../systemeditor/instancecommands.cpp" line="-30"/>
        <source>Turn %1</source>
        <translation>%1 の向きを変更</translation>
    </message>
</context>
<context>
    <name>SetLanguageCommand</name>
    <message>
        <location filename="../../builder/componentcommands.cpp" line="+13"/>
        <source>Change language and environment</source>
        <translation>言語・環境を変更</translation>
    </message>
</context>
<context>
    <name>SetSystemInfoCommand</name>
    <message>
        <location filename="../../systemeditor/systemcommands.cpp" line="+18"/>
        <source>Edit system profile</source>
        <translation>システムプロファイルを編集</translation>
    </message>
</context>
<context>
    <name>Studio::DialogPrompts</name>
    <message>
        <location filename="../../app/dialogprompts.cpp" line="+23"/>
        <source>Profile XML (*.xml)</source>
        <translation>プロファイル XML (*.xml)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Profile YAML (*.yaml *.yml)</source>
        <translation>プロファイル YAML (*.yaml *.yml)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unsaved Changes</source>
        <translation>未保存の変更</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&quot;%1&quot; has unsaved changes.</source>
        <translation>「%1」には未保存の変更があります。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Do you want to save them before closing?</source>
        <translation>閉じる前に保存しますか？</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Profiles (*.xml *.yaml *.yml)</source>
        <translation>プロファイル (*.xml *.yaml *.yml)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>All files (*)</source>
        <translation>すべてのファイル (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open Profile</source>
        <translation>プロファイルを開く</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save System Profile</source>
        <translation>システムプロファイルを保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Component Profile</source>
        <translation>コンポーネントプロファイルを保存</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>About RT Studio</source>
        <translation>RT Studio について</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;RT Studio %1&lt;/h3&gt;&lt;p&gt;An IDE for OpenRTM-aist RT-Components: design components in the Builder, compose them into systems in the System Editor.&lt;/p&gt;&lt;p&gt;Reads and writes RTC and RTS profiles (XML and YAML) as OpenRTP does.&lt;/p&gt;&lt;p&gt;Licensed under the MIT license.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RT Studio %1&lt;/h3&gt;&lt;p&gt;OpenRTM-aist の RTコンポーネントのための IDE です。ビルダでコンポーネントを設計し、システムエディタでそれらを組み合わせてシステムを構成します。&lt;/p&gt;&lt;p&gt;OpenRTP と同様に、RTCプロファイルおよびRTSプロファイル（XML と YAML）を読み書きします。&lt;/p&gt;&lt;p&gt;MIT ライセンスの下で提供されています。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>PNG image (*.png)</source>
        <translation>PNG 画像 (*.png)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG drawing (*.svg)</source>
        <translation>SVG 画像 (*.svg)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Diagram</source>
        <translation>ダイアグラムのエクスポート</translation>
    </message>
</context>
<context>
    <name>Studio::Document</name>
    <message>
        <location filename="../../app/document.cpp" line="+26"/>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the document has no file yet; use Save As</source>
        <translation>ドキュメントにはまだファイルがありません。「名前を付けて保存」を使用してください</translation>
    </message>
</context>
<context>
    <name>Studio::DocumentController</name>
    <message>
        <location filename="../../app/documentcontroller.cpp" line="+64"/>
        <source>New Component %1</source>
        <translation>新規コンポーネント %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>New System %1</source>
        <translation>新規システム %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Online Diagram %1</source>
        <translation>オンラインダイアグラム %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Saved the live system to %1</source>
        <translation>稼働中のシステムを %1 に保存しました</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Saved the live system to %1 without %n component(s)</source>
        <translation>
            <numerusform>稼働中のシステムを %1 に保存しました（%n 個のコンポーネントを除く）</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Could not save the live system to %1.</source>
        <translation>稼働中のシステムを %1 に保存できませんでした。</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+214"/>
        <source>Save Failed</source>
        <translation>保存に失敗しました</translation>
    </message>
    <message>
        <location line="-195"/>
        <source>Could not open %1.</source>
        <translation>%1 を開けませんでした。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open Failed</source>
        <translation>開けませんでした</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open documents were not changed.</source>
        <translation>開いているドキュメントは変更されていません。</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Opening %1 was cancelled</source>
        <translation>%1 を開くのを取り消しました</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Could not export the diagram to %1.</source>
        <translation>ダイアグラムを %1 にエクスポートできませんでした。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export Failed</source>
        <translation>エクスポートに失敗しました</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Exported the diagram to %1</source>
        <translation>ダイアグラムを %1 にエクスポートしました</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>could not be read</source>
        <translation>読み込めませんでした</translation>
    </message>
    <message numerus="yes">
        <location line="+11"/>
        <source>%1 was opened with %n warning(s).</source>
        <translation>
            <numerusform>%1 を開きました（警告 %n 件）。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Opened %1</source>
        <translation>%1 を開きました</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>could not be written</source>
        <translation>書き込めませんでした</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Could not save %1.</source>
        <translation>%1 を保存できませんでした。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The document stays open with its changes.</source>
        <translation>ドキュメントは変更を保持したまま開いています。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Saved %1</source>
        <translation>%1 を保存しました</translation>
    </message>
</context>
<context>
    <name>Studio::FieldRules</name>
    <message>
        <location filename="../../app/fieldrules.cpp" line="+21"/>
        <source>This field is required (it is part of the system id).</source>
        <translation>この項目は必須です (システムIDの一部です)。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;:&apos; separates the parts of the system id and cannot be used here.</source>
        <translation>「:」はシステムIDの区切り文字のため、ここでは使用できません。</translation>
    </message>
</context>
<context>
    <name>Studio::MainWindow</name>
    <message>
        <location filename="../../app/mainwindow.cpp" line="+173"/>
        <source>&amp;About RT Studio</source>
        <translation>RT Studio について(&amp;A)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;User Guide</source>
        <translation>ユーザーガイド(&amp;U)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Troubleshooting</source>
        <translation>トラブルシューティング(&amp;T)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Help on This &amp;View</source>
        <translation>このビューのヘルプ(&amp;V)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>New &amp;Component</source>
        <translation>新規コンポーネント(&amp;C)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Create a new RT-Component profile in the Builder</source>
        <translation>ビルダで新しいRTコンポーネントのプロファイルを作成</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>New &amp;System</source>
        <translation>新規システム(&amp;S)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Create a new RT System in the System Editor</source>
        <translation>システムエディタで新しいRTシステムを作成</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Open…</source>
        <translation>開く(&amp;O)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open an RTC or RTS profile (XML or YAML)</source>
        <translation>RTCプロファイルまたはRTSプロファイルを開く (XML または YAML)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save &amp;As…</source>
        <translation>名前を付けて保存(&amp;A)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Close</source>
        <translation>閉じる(&amp;C)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Export Diagram…</source>
        <translation>ダイアグラムのエクスポート(&amp;E)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&amp;Undo</source>
        <translation>元に戻す(&amp;U)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Redo</source>
        <translation>やり直し(&amp;R)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Switch to the %1 perspective</source>
        <translation>%1 パースペクティブに切り替え</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;File</source>
        <translation>ファイル(&amp;F)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open &amp;Recent</source>
        <translation>最近使ったファイルを開く(&amp;R)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Edit</source>
        <translation>編集(&amp;E)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;View</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Language</source>
        <translation>言語(&amp;L)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Online</source>
        <translation>オンライン(&amp;O)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Restore System on Live Managers…</source>
        <translation>稼働中のマネージャにシステムを復元(&amp;R)…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open a system to restore it.</source>
        <translation>復元するシステムを開いてください。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Help</source>
        <translation>ヘルプ(&amp;H)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>System Default</source>
        <translation>システムの設定に従う</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>RT Studio shows the chosen language when it starts again.</source>
        <translation>選択した言語は RT Studio の次回起動時に反映されます。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Main</source>
        <translation>メイン</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Builder</source>
        <translation>ビルダ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;p&gt;&lt;b&gt;Builder&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Design an RT-Component: File ▸ New Component, or open an RTC profile (RTC.xml or YAML) with File ▸ Open.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;ビルダ&lt;/b&gt;&lt;/p&gt;&lt;p&gt;RTコンポーネントを設計します。ファイル ▸ 新規コンポーネント を選ぶか、ファイル ▸ 開く で RTCプロファイル (RTC.xml または YAML) を開いてください。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System Editor</source>
        <translation>システムエディタ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;p&gt;&lt;b&gt;System Editor&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Compose RT-Components into a system: File ▸ New System, or open an RTS profile with File ▸ Open.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;システムエディタ&lt;/b&gt;&lt;/p&gt;&lt;p&gt;RTコンポーネントを組み合わせてシステムを構成します。ファイル ▸ 新規システム を選ぶか、ファイル ▸ 開く で RTSプロファイルを開いてください。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+8"/>
        <source>Problems</source>
        <translation>問題</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Problems (%1)</source>
        <translation>問題 (%1)</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>RT Studio</source>
        <translation>RT Studio</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Clear List</source>
        <translation>一覧をクリア</translation>
    </message>
</context>
<context>
    <name>Studio::OnlineDocks</name>
    <message>
        <location filename="../../app/onlinedocks.cpp" line="+78"/>
        <source>Name Service</source>
        <translation>ネームサービス</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Configuration</source>
        <translation>コンフィギュレーション</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Execution Contexts</source>
        <translation>実行コンテキスト</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Manager</source>
        <translation>マネージャ</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Port Monitor</source>
        <translation>ポートモニタ</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>&amp;New Online Diagram</source>
        <translation>新規オンラインダイアグラム(&amp;N)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open System Online</source>
        <translation>システムをオンラインで開く(&amp;O)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open a system to show it online.</source>
        <translation>オンラインで表示するシステムを開いてください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save Live System As…</source>
        <translation>稼働中のシステムに名前を付けて保存(&amp;S)…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open an online diagram to save its live system.</source>
        <translation>稼働中のシステムを保存するには、オンラインダイアグラムを開いてください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Compare with File…</source>
        <translation>ファイルと比較(&amp;C)…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Start &amp;Local Runtime</source>
        <translation>ローカルランタイムを起動(&amp;L)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start Local Runtime with &amp;TLS</source>
        <translation>TLS でローカルランタイムを起動(&amp;T)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop Local Runtime</source>
        <translation>ローカルランタイムを停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keep Local Runtime After Quit</source>
        <translation>終了後もローカルランタイムを残す(&amp;K)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Run System on Local Runtime</source>
        <translation>ローカルランタイムでシステムを実行(&amp;R)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open a system to run it.</source>
        <translation>実行するシステムを開いてください。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start a Manager at &amp;Boot…</source>
        <translation>起動時にマネージャを開始(&amp;B)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The Manager&apos;s Configuration</source>
        <translation>マネージャの設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manager configuration (*.conf);;All files (*)</source>
        <translation>マネージャの設定 (*.conf);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rtmanager starts with your session: %1</source>
        <translation>rtmanager はセッションの開始時に起動します: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No manager at boot: %1</source>
        <translation>起動時のマネージャを設定できませんでした: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Do Not Start a Manager at Boot</source>
        <translation>起動時にマネージャを開始しない</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Removed %1.</source>
        <translation>%1 を削除しました。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Undeploy System</source>
        <translation>システムの配備を解除(&amp;U)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open a system to undeploy it.</source>
        <translation>配備を解除するシステムを開いてください。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Activate All</source>
        <translation>すべてアクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Deactivate All</source>
        <translation>すべて非アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset All</source>
        <translation>すべてリセット</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start All</source>
        <translation>すべて開始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop All</source>
        <translation>すべて停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exit All</source>
        <translation>すべて終了</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Local runtime (TLS): name server %1, manager port %2</source>
        <translation>ローカルランタイム (TLS): ネームサーバ %1、マネージャのポート %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Local runtime: name server %1, manager port %2</source>
        <translation>ローカルランタイム：ネームサーバ %1、マネージャのポート %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Local runtime: stopped</source>
        <translation>ローカルランタイム：停止中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Local runtime: did not start</source>
        <translation>ローカルランタイム：起動できませんでした</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>RT Studio talks plain TCP since it started: quit it, run &quot;rtctl local start --tls&quot; and start RT Studio again.</source>
        <translation>RT Studio は起動時から平文の TCP で通信しています。終了して &quot;rtctl local start --tls&quot; を実行し、RT Studio を起動し直してください。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Starting the local runtime…</source>
        <translation>ローカルランタイムを起動しています…</translation>
    </message>
    <message>
        <location line="-23"/>
        <location line="+50"/>
        <source>The local runtime did not start: %1</source>
        <translation>ローカルランタイムを起動できませんでした：%1</translation>
    </message>
    <message>
        <location line="-91"/>
        <source>Undeploy System and Uninstall Its &amp;Packages</source>
        <translation>システムの配備を解除しパッケージをアンインストール(&amp;P)</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>Local runtime started.</source>
        <translation>ローカルランタイムを起動しました。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The local runtime was already running.</source>
        <translation>ローカルランタイムはすでに起動しています。</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Local runtime stopped.</source>
        <translation>ローカルランタイムを停止しました。</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Undeploying %1…</source>
        <translation>%1 の配備を解除中…</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 undeployed: %2 component(s) exited, %3 package(s) uninstalled.</source>
        <translation>%1 の配備を解除しました: コンポーネント %2 個を終了、パッケージ %3 個をアンインストール。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 was not undeployed: %2</source>
        <translation>%1 の配備を解除できませんでした: %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Restoring %1 on the local runtime…</source>
        <translation>%1 をローカルランタイムに復元しています…</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 did not run: %2</source>
        <translation>%1 を実行できませんでした：%2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 runs on the local runtime.</source>
        <translation>%1 はローカルランタイムで実行中です。</translation>
    </message>
    <message>
        <location line="+125"/>
        <source>%1 is not a system profile.</source>
        <translation>%1 はシステムプロファイルではありません。</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>Not running: %1</source>
        <translation>起動していないコンポーネント：%1</translation>
    </message>
</context>
<context>
    <name>Studio::OpeningProgress</name>
    <message>
        <location filename="../../app/openingprogress.cpp" line="+45"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Stop opening this file; open documents stay as they are</source>
        <translation>このファイルを開くのを中止します。開いているドキュメントはそのままです</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Opening %1…</source>
        <translation>%1 を開いています…</translation>
    </message>
</context>
<context>
    <name>Studio::Perspective</name>
    <message>
        <location filename="../../app/perspective.cpp" line="+135"/>
        <source>Not saved yet</source>
        <translation>未保存</translation>
    </message>
</context>
<context>
    <name>Studio::ProblemsPanel</name>
    <message>
        <location filename="../../app/problemspanel.cpp" line="+57"/>
        <location line="+75"/>
        <source>No problems.</source>
        <translation>問題はありません。</translation>
    </message>
    <message>
        <location line="-73"/>
        <source>Location</source>
        <translation>場所</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Message</source>
        <translation>メッセージ</translation>
    </message>
</context>
<context>
    <name>Studio::RtsDocument</name>
    <message>
        <location filename="../../app/rtsdocument.cpp" line="+130"/>
        <source>vendor</source>
        <translation>ベンダ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>system name</source>
        <translation>システム名</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>version</source>
        <translation>バージョン</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>abstract</source>
        <translation>概要</translation>
    </message>
</context>
<context>
    <name>Studio::RtsEditor</name>
    <message>
        <location filename="../../app/rtseditor.cpp" line="+197"/>
        <source>Plan</source>
        <translation>配置計画</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show where the planner puts each component, one lane per node</source>
        <translation>プランナーが各コンポーネントをどこに配置するかを、ノードごとのレーンで表示します</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Repository</source>
        <translation>リポジトリ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outline</source>
        <translation>アウトライン</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Properties</source>
        <translation>プロパティ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>System</source>
        <translation>システム</translation>
    </message>
</context>
<context>
    <name>Studio::SystemInfoForm</name>
    <message>
        <location filename="../../app/systeminfoform.cpp" line="+34"/>
        <source>V&amp;endor:</source>
        <translation>ベンダ(&amp;E)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;System name:</source>
        <translation>システム名(&amp;S)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Version:</source>
        <translation>バージョン(&amp;V)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(none)</source>
        <translation>(なし)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Abstract:</source>
        <translation>概要(&amp;A)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System id:</source>
        <translation>システムID：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dates:</source>
        <translation>日時：</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>%1 (not of the form RTSystem:vendor:name:version)</source>
        <translation>%1 (RTSystem:vendor:name:version の形式ではありません)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>created %1, updated %2</source>
        <translation>作成 %1、更新 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>(unknown)</source>
        <translation>(不明)</translation>
    </message>
</context>
<context>
    <name>Studio::SystemOutlineModel</name>
    <message>
        <location filename="../../app/systemoutlinemodel.cpp" line="+107"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Details</source>
        <translation>詳細</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Components</source>
        <translation>コンポーネント</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n component(s)</source>
        <translation>
            <numerusform>%n 個のコンポーネント</numerusform>
        </translation>
    </message>
    <message>
        <location line="+13"/>
        <source>data port</source>
        <translation>データポート</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>service port</source>
        <translation>サービスポート</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Connectors</source>
        <translation>コネクタ</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n connector(s)</source>
        <translation>
            <numerusform>%n 個のコネクタ</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Connector id: %1</source>
        <translation>コネクタID：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>source</source>
        <translation>ソース</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>target</source>
        <translation>ターゲット</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>data, %1</source>
        <translation>データ、%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no data type</source>
        <translation>データ型なし</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>service</source>
        <translation>サービス</translation>
    </message>
</context>
<context>
    <name>Studio::UserGuide</name>
    <message>
        <location filename="../../app/userguide.cpp" line="+26"/>
        <source>RT Studio User Guide</source>
        <translation>RT Studio ユーザーガイド</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Back</source>
        <translation>戻る</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Forward</source>
        <translation>進む</translation>
    </message>
</context>
<context>
    <name>Studio::loadDocument</name>
    <message>
        <location filename="../../app/documentloader.cpp" line="+34"/>
        <source>not an RTC or RTS profile</source>
        <translation>RTCプロファイルでもRTSプロファイルでもありません</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ComponentClipboard</name>
    <message>
        <location filename="../../systemeditor/pastecommand.cpp" line="-65"/>
        <source>The clipboard holds no components.</source>
        <translation>クリップボードにコンポーネントがありません。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The clipboard&apos;s components cannot be read: %1</source>
        <translation>クリップボードのコンポーネントを読み込めません：%1</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ComponentItem</name>
    <message>
        <location filename="../../systemeditor/scene/componentitem.cpp" line="+289"/>
        <source>Composite (%1)</source>
        <translation>複合 (%1)</translation>
    </message>
</context>
<context>
    <name>SystemEditor::CompositeDialog</name>
    <message>
        <location filename="../../systemeditor/widgets/compositedialog.cpp" line="+24"/>
        <source>InPort</source>
        <translation>InPort</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>OutPort</source>
        <translation>OutPort</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Service port</source>
        <translation>サービスポート</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Port</source>
        <translation>ポート</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Group as Composite</source>
        <translation>複合コンポーネントとしてグループ化</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&amp;Kind:</source>
        <translation>種類(&amp;K)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Members: %1</source>
        <translation>メンバー：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported ports:</source>
        <translation>エクスポートするポート：</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ConfigurationSetEditor</name>
    <message>
        <location filename="../../systemeditor/widgets/configurationseteditor.cpp" line="+59"/>
        <source>Show hidden sets</source>
        <translation>隠しセットを表示</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Activate</source>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>削除</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Add</source>
        <translation>追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>コピー</translation>
    </message>
    <message>
        <location line="+85"/>
        <source>%1 (active)</source>
        <translation>%1 (アクティブ)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Type: %1</source>
        <translation>型：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1:</source>
        <translation>%1：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2):</source>
        <translation>%1 (%2)：</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ConfigurationView</name>
    <message>
        <location filename="../../systemeditor/online/configurationview.cpp" line="+52"/>
        <source>No component selected</source>
        <translation>コンポーネントが選択されていません</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Detail (hidden sets)</source>
        <translation>詳細 (隠しセット)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add</source>
        <translation>追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>コピー</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>削除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Activate</source>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>適用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reload</source>
        <translation>再読み込み</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>%1 (active)</source>
        <translation>%1 (アクティブ)</translation>
    </message>
    <message>
        <location line="+115"/>
        <source>Done</source>
        <translation>完了</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Copy Set</source>
        <translation>セットのコピー</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Add Set</source>
        <translation>セットの追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Id of the new configuration set:</source>
        <translation>新しいコンフィギュレーションセットのID：</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ConnectorDialog</name>
    <message>
        <location filename="../../systemeditor/widgets/connectordialog.cpp" line="+54"/>
        <source>Data Connector</source>
        <translation>データコネクタ</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Name:</source>
        <translation>名前(&amp;N)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data type:</source>
        <translation>データ型：</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Which port calls connect(); the system file records it as the connector&apos;s source.</source>
        <translation>connect() を呼び出すポートです。システムファイルにはコネクタのソースとして記録されます。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect &amp;direction:</source>
        <translation>接続方向(&amp;D)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>OutPort buffer</source>
        <translation>OutPort バッファ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>InPort buffer</source>
        <translation>InPort バッファ</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Data flow</source>
        <translation>データフロー</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Interface type:</source>
        <translation>インターフェース型(&amp;I)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Marshaling type:</source>
        <translation>マーシャリング型(&amp;M)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Dataflow type:</source>
        <translation>データフロー型(&amp;D)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Subscription type:</source>
        <translation>サブスクリプション型(&amp;S)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Push &amp;rate (Hz):</source>
        <translation>プッシュ周期 (Hz)(&amp;R)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Push &amp;policy:</source>
        <translation>プッシュポリシー(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;kip count:</source>
        <translation>スキップ数(&amp;K)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Timestamp policy:</source>
        <translation>タイムスタンプポリシー(&amp;T)：</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The connector&apos;s name (rtctl con -n): the system file and the live ports know it by this name; by default the two ports&apos; names joined by &apos;_&apos;.</source>
        <translation>コネクタの名前（rtctl con -n）です。システムファイルと稼働中のポートはこの名前でコネクタを識別します。既定では 2 つのポートの名前を「_」でつないだものです。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Which port calls connect(). The system file records that port as the connector&apos;s source; data flows from the OutPort either way.</source>
        <translation>どちらのポートが connect() を呼ぶかです。システムファイルはそのポートをコネクタの接続元として記録します。データはどちらの場合も OutPort から InPort へ流れます。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Properties without a field above, sent with the connector as they are (rtctl con -p KEY=VALUE): dataport.* settings of other connector types, or your own.</source>
        <translation>上の欄にないプロパティで、そのままコネクタとともに送られます（rtctl con -p KEY=VALUE）。他のコネクタ型の dataport.* 設定や独自のプロパティに使います。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dataport.interface_type: how samples travel. corba_cdr sends them as CORBA calls between any two processes; other types need both sides to offer them.</source>
        <translation>dataport.interface_type：データの運び方です。corba_cdr はどの二つのプロセスの間でも CORBA の呼び出しで送ります。ほかの種類は両側がそれを提供している必要があります。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dataport.marshaling_type: how samples are encoded on the way (cdr unless the components offer another serializer).</source>
        <translation>dataport.marshaling_type：送る途中でのデータの符号化です（コンポーネントが別のシリアライザを提供していなければ cdr）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dataport.dataflow_type: push, the OutPort sends each sample as it is written; pull, the InPort asks for the latest sample when its component reads.</source>
        <translation>dataport.dataflow_type：push では OutPort が書き込まれたデータをそのつど送り、pull では InPort のコンポーネントが読むときに最新のデータを問い合わせます。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dataport.subscription_type (push only): flush sends at once in the writer&apos;s thread; new sends the newest from a thread of the connector, skipping what it could not send yet; periodic sends at the push rate.</source>
        <translation>dataport.subscription_type（push のみ）：flush は書き込んだスレッドですぐに送り、new はコネクタのスレッドから最新のデータを送り（まだ送れていないものは飛ばします）、periodic はプッシュレートで送ります。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dataport.push_rate: how many times a second a periodic subscription sends.</source>
        <translation>dataport.push_rate：periodic のサブスクリプションが 1 秒に何回送るかです。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dataport.publisher.push_policy: what each send takes from the OutPort buffer: all of it, the oldest (fifo), every n-th (skip) or the newest (new).</source>
        <translation>dataport.publisher.push_policy：1 回の送信で OutPort のバッファから何を取り出すかです。すべて（all）、最も古いもの（fifo）、n 個おき（skip）、最新のもの（new）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dataport.publisher.skip_count: with the skip policy, how many samples are left out between two sent ones.</source>
        <translation>dataport.publisher.skip_count：skip ポリシーのとき、送る二つのデータの間で飛ばす数です。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dataport.timestamp_policy: when a sample&apos;s time stamp is set: when it is written, sent, received or read.</source>
        <translation>dataport.timestamp_policy：データのタイムスタンプを付けるときです。書き込み時、送信時、受信時、読み出し時のいずれか。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>buffer.length: how many samples the buffer holds.</source>
        <translation>buffer.length：バッファが保持するデータの数です。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>buffer.write.full_policy: what a write into a full buffer does: overwrite the oldest sample, do nothing (the sample is lost), or block until there is room or the write timeout passes.</source>
        <translation>buffer.write.full_policy：満杯のバッファへの書き込みの動作です。最も古いデータを上書きする（overwrite）、何もしない（データは失われます、do_nothing）、空きができるか書き込みタイムアウトまで待つ（block）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>buffer.write.timeout: how long a blocked write waits, in seconds.</source>
        <translation>buffer.write.timeout：待っている書き込みが待つ時間（秒）です。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>buffer.read.empty_policy: what a read from an empty buffer does: read the last sample again (readback), do nothing, or block until a sample comes or the read timeout passes.</source>
        <translation>buffer.read.empty_policy：空のバッファからの読み出しの動作です。最後のデータをもう一度読む（readback）、何もしない（do_nothing）、データが来るか読み出しタイムアウトまで待つ（block）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>buffer.read.timeout: how long a blocked read waits, in seconds.</source>
        <translation>buffer.read.timeout：待っている読み出しが待つ時間（秒）です。</translation>
    </message>
    <message>
        <location line="-71"/>
        <location line="+96"/>
        <source>default</source>
        <translation>デフォルト</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length:</source>
        <translation>長さ：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Full policy:</source>
        <translation>フル時のポリシー：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write timeout (s):</source>
        <translation>書き込みタイムアウト (秒)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Empty policy:</source>
        <translation>エンプティ時のポリシー：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read timeout (s):</source>
        <translation>読み出しタイムアウト (秒)：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Properties</source>
        <translation>プロパティ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Add</source>
        <translation>追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>削除</translation>
    </message>
</context>
<context>
    <name>SystemEditor::DiagramExport</name>
    <message>
        <location filename="../../systemeditor/scene/diagramexport.cpp" line="+48"/>
        <source>RT System diagram</source>
        <translation>RTシステムダイアグラム</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+6"/>
        <source>Cannot write &quot;%1&quot;.</source>
        <translation>「%1」に書き込めません。</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Unknown image format &quot;%1&quot;: use .svg or .png.</source>
        <translation>不明な画像形式「%1」です。.svg または .png を使用してください。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot write &quot;%1&quot;: %2</source>
        <translation>「%1」に書き込めません：%2</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Cannot read &quot;%1&quot;.</source>
        <translation>「%1」を読み込めません。</translation>
    </message>
</context>
<context>
    <name>SystemEditor::DriftView</name>
    <message>
        <location filename="../../systemeditor/online/driftview.cpp" line="+39"/>
        <source>Compare %1 with the Live System</source>
        <translation>%1 と稼働中のシステムの比較</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Difference</source>
        <translation>差分</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>In the file</source>
        <translation>ファイル内</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Live</source>
        <translation>稼働中</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Refresh</source>
        <translation>更新</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Comparing with the live system…</source>
        <translation>稼働中のシステムと比較しています…</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>The live system matches %1.</source>
        <translation>稼働中のシステムは %1 と一致しています。</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n difference(s) between %1 and the live system.</source>
        <translation>
            <numerusform>%1 と稼働中のシステムの間に %n 件の差分があります。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SystemEditor::ElementListEditor</name>
    <message>
        <location filename="../../systemeditor/widgets/elementlisteditor.cpp" line="+77"/>
        <source>Add element</source>
        <translation>要素を追加</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Remove element %1</source>
        <translation>要素 %1 を削除</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ElementRules</name>
    <message>
        <location line="-71"/>
        <source>Element %1: %2</source>
        <translation>要素 %1：%2</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ExecutionContextModel</name>
    <message>
        <location filename="../../systemeditor/online/executioncontextmodel.cpp" line="+45"/>
        <source>owned</source>
        <translation>所有</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>participating</source>
        <translation>参加</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+28"/>
        <source>Running</source>
        <translation>実行中</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>Stopped</source>
        <translation>停止中</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>(not answering)</source>
        <translation>(応答なし)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Id</source>
        <translation>ID</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Relation</source>
        <translation>関係</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>種類</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate (Hz)</source>
        <translation>周期 (Hz)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Component State</source>
        <translation>コンポーネントの状態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Owner</source>
        <translation>オーナー</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Participants</source>
        <translation>参加者</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ExecutionContextView</name>
    <message>
        <location filename="../../systemeditor/online/executioncontextview.cpp" line="+62"/>
        <source>No component selected</source>
        <translation>コンポーネントが選択されていません</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+224"/>
        <source>Start</source>
        <translation>開始</translation>
    </message>
    <message>
        <location line="-223"/>
        <location line="+224"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="-223"/>
        <location line="+224"/>
        <source>Activate</source>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="-223"/>
        <location line="+224"/>
        <source>Deactivate</source>
        <translation>非アクティブ化</translation>
    </message>
    <message>
        <location line="-223"/>
        <location line="+224"/>
        <source>Reset</source>
        <translation>リセット</translation>
    </message>
    <message>
        <location line="-214"/>
        <source>Attach...</source>
        <translation>アタッチ...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Detach...</source>
        <translation>デタッチ...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Make another live component take part in this context</source>
        <translation>稼働中の別のコンポーネントをこのコンテキストに参加させます</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Take a participant out of this context</source>
        <translation>参加者をこのコンテキストから外します</translation>
    </message>
    <message>
        <location line="+10"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set Rate</source>
        <translation>周期を設定</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Done</source>
        <translation>完了</translation>
    </message>
    <message>
        <location line="+94"/>
        <location line="+11"/>
        <source>%1: no execution context with index %2</source>
        <translation>%1：インデックス %2 の実行コンテキストはありません</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No other live component</source>
        <translation>稼働中の他のコンポーネントはありません</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No participant</source>
        <translation>参加者はいません</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Attach</source>
        <translation>アタッチ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Detach</source>
        <translation>デタッチ</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ManagerView</name>
    <message>
        <location filename="../../systemeditor/online/managerview.cpp" line="+89"/>
        <source>No manager selected</source>
        <translation>マネージャが選択されていません</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Details</source>
        <translation>詳細</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Delete Component</source>
        <translation>コンポーネントを削除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load</source>
        <translation>ロード</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unload</source>
        <translation>アンロード</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shutdown</source>
        <translation>シャットダウン</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>更新</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Install Package…</source>
        <translation>パッケージをインストール…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Install a component package by the URL of its .deb in a repository (rtctl node install)</source>
        <translation>リポジトリ内の .deb の URL でコンポーネントパッケージをインストール (rtctl と同じ操作)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Uninstall</source>
        <translation>アンインストール</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Install Component Package</source>
        <translation>コンポーネントパッケージのインストール</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URL of the package in a repository:</source>
        <translation>リポジトリ内のパッケージの URL:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Create Component</source>
        <translation>コンポーネントの生成</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Add Parameter</source>
        <translation>パラメータを追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Create</source>
        <translation>生成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Type:</source>
        <translation>型：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Target manager:</source>
        <translation>対象マネージャ：</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Slave managers</source>
        <translation>スレーブマネージャ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Components</source>
        <translation>コンポーネント</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Factories</source>
        <translation>ファクトリ</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Loaded modules</source>
        <translation>ロード済みモジュール</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Loadable modules</source>
        <translation>ロード可能なモジュール</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Installed packages</source>
        <translation>インストール済みパッケージ</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1 (this manager)</source>
        <translation>%1 (このマネージャ)</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Done</source>
        <translation>完了</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Installing %1…</source>
        <translation>%1 をインストール中…</translation>
    </message>
</context>
<context>
    <name>SystemEditor::NameServiceModel</name>
    <message>
        <location filename="../../systemeditor/online/nameservicemodel.cpp" line="+282"/>
        <source>not answering</source>
        <translation>応答なし</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>zombie</source>
        <translation>ゾンビ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unreachable</source>
        <translation>到達不能</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>TLS</source>
        <translation>TLS</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>TLS: %1</source>
        <translation>TLS: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1
Encrypted with TLS</source>
        <translation>%1
TLS で暗号化されています</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1
Encrypted with TLS; the server proved to be &quot;%2&quot; with a certificate of your authority</source>
        <translation>%1
TLS で暗号化されています。サーバは認証局の証明書で &quot;%2&quot; であることを示しました</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Name</source>
        <translation>名前</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>状態</translation>
    </message>
</context>
<context>
    <name>SystemEditor::NameServiceView</name>
    <message>
        <location filename="../../systemeditor/online/nameserviceview.cpp" line="+143"/>
        <source>host[:port]</source>
        <translation>ホスト[:ポート]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add</source>
        <translation>追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add a name server (port 2809 when none is given)</source>
        <translation>ネームサーバを追加します（ポート省略時は2809）</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+188"/>
        <source>Refresh</source>
        <translation>更新</translation>
    </message>
    <message>
        <location line="-187"/>
        <source>Delete Zombies</source>
        <translation>ゾンビを削除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove every name whose object does not answer</source>
        <translation>オブジェクトが応答しない名前をすべて削除します</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Filter</source>
        <translation>フィルタ</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>&apos;%1&apos; is not a new name server address</source>
        <translation>「%1」は新しいネームサーバのアドレスではありません</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Activate</source>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Deactivate</source>
        <translation>非アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>リセット</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exit</source>
        <translation>終了</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Shutdown</source>
        <translation>シャットダウン</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restart</source>
        <translation>再起動</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delete Zombie</source>
        <translation>ゾンビを削除</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delete All Zombies</source>
        <translation>すべてのゾンビを削除</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove Name Server</source>
        <translation>ネームサーバを削除</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Show IOR</source>
        <translation>IORを表示</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>IOR of %1</source>
        <translation>%1のIOR</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 answers again</source>
        <translation>%1が再び応答しました</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 does not answer: %2</source>
        <translation>%1が応答しません：%2</translation>
    </message>
</context>
<context>
    <name>SystemEditor::OnlineDiagram</name>
    <message>
        <location filename="../../systemeditor/online/onlinediagram.cpp" line="+120"/>
        <source>Activate All</source>
        <translation>すべてアクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Deactivate All</source>
        <translation>すべて非アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset All</source>
        <translation>すべてリセット</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start All</source>
        <translation>すべて開始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop All</source>
        <translation>すべて停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exit All</source>
        <translation>すべて終了</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Keep Running</source>
        <translation>稼働を維持</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open a saved system online to keep it running when a node dies</source>
        <translation>ノード停止時にも稼働を維持するには、保存したシステムをオンラインで開いてください</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%v of %m</source>
        <translation>%v / %m</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location line="+187"/>
        <source>Unreachable: %1</source>
        <translation>到達不能：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unreachable: </source>
        <translation>到達不能：</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>Activating</source>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deactivating</source>
        <translation>非アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resetting</source>
        <translation>リセット</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Exiting</source>
        <translation>終了</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Starting</source>
        <translation>開始</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stopping</source>
        <translation>停止</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%1 %n component(s)…</source>
        <translation>
            <numerusform>%1：%n 個のコンポーネントを処理中…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Cancelling: the waits end, the actions not yet sent are not made…</source>
        <translation>取り消し中: 待機を終了し、まだ送っていない操作は行いません…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancelling: the calls under way finish, the others are not made…</source>
        <translation>中止しています：実行中の呼び出しは完了し、残りは行いません…</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>%1: %2 of %n component(s) done</source>
        <translation>
            <numerusform>%1：%n 個中 %2 個のコンポーネントが完了</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>, %n failed</source>
        <translation>
            <numerusform>、%n 個失敗</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>, %n cancelled</source>
        <translation>
            <numerusform>、%n 個中止</numerusform>
        </translation>
    </message>
    <message>
        <location line="+32"/>
        <source>&amp;Monitor Port</source>
        <translation>ポートをモニタ(&amp;M)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Disconnect</source>
        <translation>切断</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Activate</source>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deactivate</source>
        <translation>非アクティブ化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>リセット</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Start</source>
        <translation>開始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Exit</source>
        <translation>終了</translation>
    </message>
    <message>
        <location filename="../../systemeditor/online/onlinediagramsave.cpp" line="+55"/>
        <source>Reading the live system…</source>
        <translation>稼働中のシステムを読み込んでいます…</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>None of the components on the diagram answered.</source>
        <translation>ダイアグラム上のコンポーネントはどれも応答しませんでした。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 could not be written.</source>
        <translation>%1に書き込めませんでした。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Saved %1</source>
        <translation>%1を保存しました</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saved %1 without: %2</source>
        <translation>%1を保存しました（次を除く：%2）</translation>
    </message>
    <message>
        <location filename="../../systemeditor/online/onlinediagramplan.cpp" line="+36"/>
        <source>Runs the system&apos;s StartUp and Activation plan (as rtctl start)</source>
        <translation>システムの StartUp と Activation の計画を実行します (rtctl start と同じ)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Runs the system&apos;s Deactivation and ShutDown plan (as rtctl stop)</source>
        <translation>システムの Deactivation と ShutDown の計画を実行します (rtctl stop と同じ)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>When a node of the system stops answering, move its components to the others and start them there (as rtctl deploy --watch)</source>
        <translation>システムのノードが応答しなくなったら、そのコンポーネントを他のノードへ移して起動します (rtctl と同じ操作)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Starting the system</source>
        <translation>システムを開始中</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stopping the system</source>
        <translation>システムを停止中</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: finding its components…</source>
        <translation>%1: コンポーネントを探しています…</translation>
    </message>
    <message numerus="yes">
        <location line="+46"/>
        <location line="+32"/>
        <source>%1: %n action(s) done</source>
        <translation>
            <numerusform>%1: %n 件の操作が完了</numerusform>
        </translation>
    </message>
    <message>
        <location line="-30"/>
        <source>, waiting: %1</source>
        <translation>、待機中: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+26"/>
        <source>%1: cancelled after %n action(s)</source>
        <translation>
            <numerusform>%1: %n 件の操作の後に取り消しました</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 failed: %2</source>
        <translation>%1 に失敗しました: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>, %n optional failed</source>
        <translation>
            <numerusform>、任意のもの %n 件が失敗</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1.</source>
        <extracomment>The finished status line as a sentence (its full stop).</extracomment>
        <translation>%1。</translation>
    </message>
    <message>
        <location filename="../../systemeditor/online/onlinediagramheal.cpp" line="+51"/>
        <source>Keep Running is off.</source>
        <translation>稼働の維持はオフです。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Keep Running: watching the system&apos;s nodes.</source>
        <translation>稼働の維持: システムのノードを監視中。</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>Keep Running: %1</source>
        <translation>稼働の維持: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Keep Running could not heal the system: %1</source>
        <translation>稼働の維持でシステムを回復できませんでした: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 to %2</source>
        <translation>%1 を %2 へ</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Keep Running moved %1.</source>
        <translation>稼働の維持により %1 移動しました。</translation>
    </message>
</context>
<context>
    <name>SystemEditor::OnlineIcons</name>
    <message>
        <location filename="../../systemeditor/online/onlineicons.cpp" line="+130"/>
        <source>Created</source>
        <translation>生成済み</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inactive</source>
        <translation>非アクティブ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Active</source>
        <translation>アクティブ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Error</source>
        <translation>エラー</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Unknown</source>
        <translation>不明</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>root</source>
        <translation>ルート</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>server</source>
        <translation>サーバ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>context</source>
        <translation>コンテキスト</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>component</source>
        <translation>コンポーネント</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>manager</source>
        <translation>マネージャ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>object</source>
        <translation>オブジェクト</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>zombie</source>
        <translation>ゾンビ</translation>
    </message>
</context>
<context>
    <name>SystemEditor::OnlineService</name>
    <message>
        <location filename="../../systemeditor/online/onlineservice.cpp" line="+40"/>
        <source>The call to %1 failed with an unexpected error</source>
        <translation>%1の呼び出しが予期しないエラーで失敗しました</translation>
    </message>
</context>
<context>
    <name>SystemEditor::OverviewWidget</name>
    <message>
        <location filename="../../systemeditor/widgets/overviewwidget.cpp" line="+21"/>
        <source>Overview: click to show that part of the diagram</source>
        <translation>全体図：クリックするとダイアグラムのその部分を表示します</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ParameterEditor</name>
    <message>
        <location filename="../../systemeditor/online/parametereditor.cpp" line="+53"/>
        <source>Constraint: %1</source>
        <translation>制約：%1</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ParameterRule</name>
    <message>
        <location filename="../../systemeditor/online/parameterrule.cpp" line="+212"/>
        <source>&apos;%1&apos; is not one of %2</source>
        <translation>「%1」は次のいずれでもありません：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; is not a number</source>
        <translation>「%1」は数値ではありません</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; does not satisfy %2</source>
        <translation>「%1」は%2を満たしていません</translation>
    </message>
</context>
<context>
    <name>SystemEditor::PlanCardItem</name>
    <message>
        <location filename="../../systemeditor/plan/plancarditem.cpp" line="+35"/>
        <source>Runs in a process of its own</source>
        <translation>専用のプロセスで動作します</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shares process %1</source>
        <translation>プロセス %1 を共有します</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Installs %1 here</source>
        <translation>ここに %1 をインストールします</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pinned here: drag it to another node to move the pin</source>
        <translation>ここに固定されています。別のノードへドラッグすると固定先が移ります</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Free: drag it to a node to pin it there</source>
        <translation>固定されていません。ノードへドラッグするとそこに固定します</translation>
    </message>
</context>
<context>
    <name>SystemEditor::PlanLanes</name>
    <message>
        <location filename="../../systemeditor/plan/planlanes.cpp" line="+79"/>
        <source>system</source>
        <translation>システム</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 (%3)</source>
        <translation>%1：%2（%3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 — no node meets it; closest %3 has %4</source>
        <translation>%1：%2 — 満たすノードがありません。最も近い %3 は %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Install %1 %2 on %3</source>
        <translation>%3 に %1 %2 をインストール</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Create %1 (%2) on %3 in process %4</source>
        <translation>%3 のプロセス %4 に %1（%2）を生成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Create %1 (%2) on %3 in a process of its own</source>
        <translation>%3 の専用プロセスに %1（%2）を生成</translation>
    </message>
</context>
<context>
    <name>SystemEditor::PlanScene</name>
    <message>
        <location filename="../../systemeditor/plan/planscene.cpp" line="+52"/>
        <source>Not placed</source>
        <translation>未配置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1
CPU load %2 per CPU</source>
        <translation>%1
CPU あたりの負荷 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>
Installs: %1</source>
        <translation>
インストール：%1</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>Pin to %1</source>
        <translation>%1 に固定</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Free (Let the Planner Choose)</source>
        <translation>固定を解除（プランナーに任せる）</translation>
    </message>
</context>
<context>
    <name>SystemEditor::PlanView</name>
    <message>
        <location filename="../../systemeditor/plan/planview.cpp" line="+143"/>
        <source>Unmet Requirements</source>
        <translation>満たされない要件</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+25"/>
        <source>Dry Run</source>
        <translation>ドライラン</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Open Facts…</source>
        <translation>ファクトを開く…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read Managers…</source>
        <translation>マネージャから読む…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Repository…</source>
        <translation>リポジトリ…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Re-plan</source>
        <translation>再計画</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Deploy</source>
        <translation>デプロイ</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open Node Facts</source>
        <translation>ノードのファクトを開く</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node facts (*.yaml *.yml *.json);;All files (*)</source>
        <translation>ノードのファクト (*.yaml *.yml *.json);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Component Repository</source>
        <translation>コンポーネントリポジトリ</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Reading the repository…</source>
        <translation>リポジトリを読んでいます…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Could not read the repository: %1</source>
        <translation>リポジトリを読めませんでした：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Packages in the repository: %1.</source>
        <translation>リポジトリのパッケージ：%1。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Read Managers</source>
        <translation>マネージャから読む</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Managers to plan on (corbaloc or name-service paths, separated by commas):</source>
        <translation>配置先のマネージャ（corbaloc またはネームサービスのパスをコンマで区切って）：</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Could not read the node facts: %1</source>
        <translation>ノードのファクトを読めませんでした：%1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Reading the managers…</source>
        <translation>マネージャから読んでいます…</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Nodes read: %1.</source>
        <translation>読んだノード：%1。</translation>
    </message>
    <message>
        <location line="+131"/>
        <source>Install, create and connect the components as planned (opens the Restore dialog)</source>
        <translation>計画どおりにコンポーネントをインストール・生成・接続します (復元ダイアログを開きます)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Deploying needs the online tools of RT Studio&apos;s main window</source>
        <translation>配備には RT Studio のメインウィンドウのオンラインツールが必要です</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Not read: %1</source>
        <translation>読めなかったもの：%1</translation>
    </message>
    <message>
        <location line="-161"/>
        <source>Open a facts file or read the managers to plan on their nodes.</source>
        <translation>ファクトのファイルを開くかマネージャから読むと、そのノードへの配置を計画します。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Planning…</source>
        <translation>計画しています…</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Cancelled.</source>
        <translation>キャンセルしました。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Nothing to deploy: there is no plan.</source>
        <translation>デプロイするものはありません：計画がありません。</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>Not planned yet.</source>
        <translation>まだ計画していません。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No plan: requirements that no node meets, in red: %1.</source>
        <translation>計画なし：どのノードも満たさない要件（赤で表示）：%1。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Components placed: %1; packages to install: %2; connectors between hosts: %3 Hz; solved in %4 ms.</source>
        <translation>配置したコンポーネント：%1、インストールするパッケージ：%2、ホスト間のコネクタ：%3 Hz、求解 %4 ms。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not proven best: the solver&apos;s time ran out.</source>
        <translation>最良とは証明されていません：ソルバーの時間切れです。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The system changed since: re-plan to see where everything goes now.</source>
        <translation>その後システムが変更されました。再計画すると現在の配置がわかります。</translation>
    </message>
</context>
<context>
    <name>SystemEditor::PortItem</name>
    <message>
        <location filename="../../systemeditor/scene/portitem.cpp" line="+23"/>
        <source>InPort</source>
        <translation>InPort</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>OutPort</source>
        <translation>OutPort</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Service port</source>
        <translation>サービスポート</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Port (no RTC profile)</source>
        <translation>ポート（RTCプロファイルなし）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>required</source>
        <translation>要求</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>provided</source>
        <translation>提供</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Data type: %1</source>
        <translation>データ型：%1</translation>
    </message>
</context>
<context>
    <name>SystemEditor::PortMonitor</name>
    <message>
        <location filename="../../systemeditor/online/portmonitor.cpp" line="+110"/>
        <source>%1: data type %2 is in none of the IDL files</source>
        <translation>%1：データ型 %2 はどの IDL ファイルにもありません</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>&amp;Remove</source>
        <translation>削除(&amp;R)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Pause</source>
        <translation>一時停止(&amp;P)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How many seconds of samples are kept and plotted</source>
        <translation>サンプルを保持してプロットする秒数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>all</source>
        <translation>すべて</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> /s</source>
        <translation> 件/秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>At most this many samples a second are kept of each port (all: every sample)</source>
        <translation>各ポートで 1 秒間に保持するサンプル数の上限（すべて: 全サンプル）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;xport CSV…</source>
        <translation>CSV をエクスポート(&amp;X)…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Watched ports (pick one on an online diagram: Monitor Port)</source>
        <translation>モニタ中のポート（オンラインダイアグラムでポートを選び「ポートをモニタ」）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Window:</source>
        <translation>表示期間：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rate:</source>
        <translation>レート:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Received</source>
        <translation>受信時刻</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Seconds</source>
        <translation>秒</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1 is no OutPort: only what an OutPort sends can be watched.</source>
        <translation>%1 は OutPort ではありません。モニタできるのは OutPort が送るデータだけです。</translation>
    </message>
    <message numerus="yes">
        <location line="+134"/>
        <source>%1 · %n sample(s) kept</source>
        <translation>
            <numerusform>%1 · %n 個のサンプルを保持</numerusform>
        </translation>
    </message>
    <message>
        <location line="+78"/>
        <source>%1 is not watched.</source>
        <translation>%1 はモニタしていません。</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+13"/>
        <source>Cannot write %1: %2</source>
        <translation>%1 に書き込めません：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Export Samples</source>
        <translation>サンプルをエクスポート</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV ファイル (*.csv)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Saved the samples of %1 to %2</source>
        <translation>%1 のサンプルを %2 に保存しました</translation>
    </message>
</context>
<context>
    <name>SystemEditor::PropertiesPanel</name>
    <message>
        <location filename="../../systemeditor/widgets/propertiespanel.cpp" line="+51"/>
        <source>Select a component or a connector to see its properties.</source>
        <translation>プロパティを表示するには、コンポーネントまたはコネクタを選択してください。</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Instance name:</source>
        <translation>インスタンス名：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type name:</source>
        <translation>型名：</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+19"/>
        <source>Id:</source>
        <translation>ID：</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>Path URI:</source>
        <translation>パスURI：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Configuration sets&lt;/b&gt;</source>
        <translation>&lt;b&gt;コンフィギュレーションセット&lt;/b&gt;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Name:</source>
        <translation>名前：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kind:</source>
        <translation>種類：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Source:</source>
        <translation>接続元：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Target:</source>
        <translation>接続先：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Property</source>
        <translation>プロパティ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Edit Connector…</source>
        <translation>コネクタを編集…</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Data port connector</source>
        <translation>データポートコネクタ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Service port connector</source>
        <translation>サービスポートコネクタ</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>data type</source>
        <translation>データ型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interface type</source>
        <translation>インターフェース型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dataflow type</source>
        <translation>データフロー型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subscription type</source>
        <translation>サブスクリプション型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>push interval</source>
        <translation>プッシュ周期</translation>
    </message>
</context>
<context>
    <name>SystemEditor::RepositoryView</name>
    <message>
        <location filename="../../systemeditor/widgets/repositoryview.cpp" line="+35"/>
        <source>Add Files…</source>
        <translation>ファイルを追加…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add Folder…</source>
        <translation>フォルダを追加…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add Repository URL…</source>
        <translation>リポジトリ URL を追加…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add a component repository served over http or https (rtctl repo)</source>
        <translation>http または https で提供されるコンポーネントリポジトリ (rtctl で作成) を追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reload</source>
        <translation>再読み込み</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Add a folder of RTC profiles, or a component repository folder</source>
        <translation>RTC プロファイルのフォルダ、またはコンポーネントリポジトリのフォルダを追加します</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Component repository %1 read.</source>
        <translation>コンポーネントリポジトリ %1 を読み込みました。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove Package from Repository</source>
        <translation>パッケージをリポジトリから削除</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Only a package of a component repository folder can be removed.</source>
        <translation>削除できるのはコンポーネントリポジトリのフォルダ内のパッケージだけです。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Package %1 removed from its repository.</source>
        <translation>パッケージ %1 をリポジトリから削除しました。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Package %1 was not removed: %2</source>
        <translation>パッケージ %1 を削除できませんでした: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&quot;%1&quot; does not exist.</source>
        <translation>「%1」は存在しません。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Add RTC Profiles</source>
        <translation>RTCプロファイルを追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTC profiles (*.xml *.yaml *.yml)</source>
        <translation>RTCプロファイル (*.xml *.yaml *.yml)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Add Folder of RTC Profiles</source>
        <translation>RTCプロファイルのフォルダを追加</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Add Component Repository</source>
        <translation>コンポーネントリポジトリを追加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Repository URL (http, https or file):</source>
        <translation>リポジトリ URL (http、https または file):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reading component repository %1…</source>
        <translation>コンポーネントリポジトリ %1 を読み込み中…</translation>
    </message>
</context>
<context>
    <name>SystemEditor::RestoreDialog</name>
    <message>
        <location filename="../../systemeditor/online/restoredialog.cpp" line="+46"/>
        <source>existing</source>
        <translation>既存</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>create</source>
        <translation>生成</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>missing</source>
        <translation>不足</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Restore System</source>
        <translation>システムの復元</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Component</source>
        <translation>コンポーネント</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Type</source>
        <translation>型</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mapping</source>
        <translation>対応付け</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Live path / note</source>
        <translation>稼働中のパス / 備考</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Target manager</source>
        <translation>対象マネージャ</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+23"/>
        <source>Restore</source>
        <translation>復元</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>Activate</source>
        <translation>アクティブ化</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Install</source>
        <translation>インストール</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connector</source>
        <translation>コネクタ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>From</source>
        <translation>接続元</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>To</source>
        <translation>接続先</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Connect</source>
        <translation>接続</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+130"/>
        <source>Mapping the live system…</source>
        <translation>稼働中のシステムと対応付けています…</translation>
    </message>
    <message>
        <location line="-125"/>
        <source>Dry Run</source>
        <translation>ドライラン</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cancel Restore</source>
        <translation>復元を中止</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cancelling: undoing what was done…</source>
        <translation>中止しています：行ったことを元に戻しています…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Create missing components through a manager:</source>
        <translation>不足しているコンポーネントをマネージャで生成：</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>An rtshell path (/host:2809/host.host_cxt/manager.mgr) or a corbaloc (corbaloc::host:2810)</source>
        <translation>rtshellのパス（/host:2809/host.host_cxt/manager.mgr）またはcorbaloc（corbaloc::host:2810）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Install missing component types from repository:</source>
        <translation>不足しているコンポーネント型をリポジトリからインストール:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>http://host/repo/, file:///path or a folder</source>
        <translation>http://host/repo/、file:///path またはフォルダ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A component repository made with rtctl repo. Each manager that creates components installs the packages of the types it cannot load, verified with its own keyring.</source>
        <translation>rtctl repo で作成したコンポーネントリポジトリ。コンポーネントを生成する各マネージャが、ロードできない型のパッケージを自身の鍵束で検証してインストールします。</translation>
    </message>
    <message>
        <location line="+146"/>
        <source>host:port of the manager that runs it; empty: %1</source>
        <translation>これを実行するマネージャのホスト:ポート。空欄の場合：%1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 is required but not found</source>
        <translation>%1は必須ですが見つかりません</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tick &quot;Create missing components&quot; to create them through a manager.</source>
        <translation>「不足しているコンポーネントをマネージャで生成」にチェックを入れると、マネージャで生成します。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Choose the manager that creates the missing components.</source>
        <translation>不足しているコンポーネントを生成するマネージャを選択してください。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ready to restore.</source>
        <translation>復元の準備ができました。</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not selected</source>
        <translation>未選択</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>planned: install %1 %2 on %3 (%4)</source>
        <translation>予定: %3 に %1 %2 をインストール (%4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>planned: %1</source>
        <translation>予定：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>skipped: connect %1 (not selected)</source>
        <translation>スキップ：%1の接続（未選択）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Dry run: nothing was changed.</source>
        <translation>ドライラン：何も変更していません。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Restoring…</source>
        <translation>復元しています…</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Restored.</source>
        <translation>復元しました。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Restore failed: %1</source>
        <translation>復元に失敗しました：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Failed: %1</source>
        <translation>失敗：%1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Restoring: %1…</source>
        <translation>復元中：%1…</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Nothing had to be rolled back.</source>
        <translation>ロールバックの必要はありませんでした。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rolled back: %1</source>
        <translation>ロールバック済み：%1</translation>
    </message>
</context>
<context>
    <name>SystemEditor::RtcRepository</name>
    <message>
        <location filename="../../systemeditor/rtcrepository.cpp" line="+211"/>
        <source>The file is no RTC profile.</source>
        <translation>このファイルはRTCプロファイルではありません。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>The RTC profile of package %1 %2 cannot be read.</source>
        <translation>パッケージ %1 %2 の RTC プロファイルを読み込めません。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>(no category)</source>
        <translation>（カテゴリなし）</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Unreadable files</source>
        <translation>読み込めないファイル</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1
package %2 %3 in %4</source>
        <translation>%1
%4 のパッケージ %2 %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Component</source>
        <translation>コンポーネント</translation>
    </message>
</context>
<context>
    <name>SystemEditor::SaveProfileDialog</name>
    <message>
        <location filename="../../systemeditor/widgets/saveprofiledialog.cpp" line="+30"/>
        <source>System Profile Information</source>
        <translation>システムプロファイル情報</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Vendor:</source>
        <translation>ベンダ(&amp;V)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>System &amp;name:</source>
        <translation>システム名(&amp;N)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>V&amp;ersion:</source>
        <translation>バージョン(&amp;E)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Abstract:</source>
        <translation>概要(&amp;A)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Required components:</source>
        <translation>必須コンポーネント(&amp;R)：</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Edit system profile information</source>
        <translation>システムプロファイル情報の編集</translation>
    </message>
</context>
<context>
    <name>SystemEditor::ServiceConnectorDialog</name>
    <message>
        <location filename="../../systemeditor/widgets/serviceconnectordialog.cpp" line="+68"/>
        <source>Service Connector</source>
        <translation>サービスコネクタ</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Consumer (required)</source>
        <translation>コンシューマ（要求）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Provider (provided)</source>
        <translation>プロバイダ（提供）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Name:</source>
        <translation>名前(&amp;N)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect &amp;direction:</source>
        <translation>接続方向(&amp;D)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Interface mapping (automatic pairs by instance name):</source>
        <translation>インターフェースの対応付け（インスタンス名で自動的に対応）：</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Which port calls connect(); the system file records it as the connector&apos;s source.</source>
        <translation>connect() を呼び出すポートです。システムファイルにはコネクタの接続元として記録されます。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>first port</source>
        <translation>1つ目のポート</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>second port</source>
        <translation>2つ目のポート</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 → %2 (%1 connects)</source>
        <translation>%1 → %2（%1が接続）</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>automatic</source>
        <translation>自動</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 (not on the other port)</source>
        <translation>%1（相手のポートにありません）</translation>
    </message>
    <message>
        <location line="+73"/>
        <location line="+16"/>
        <source>Interface &quot;%1&quot; has no counterpart on the other port.</source>
        <translation>インターフェース「%1」に対応するものが相手のポートにありません。</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>&quot;%1&quot; requires %2 but &quot;%3&quot; provides %4.</source>
        <translation>「%1」は%2を要求していますが、「%3」は%4を提供しています。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&quot;%1&quot; uses &quot;%2&quot; of another instance name (%3, %4).</source>
        <translation>「%1」は別のインスタンス名の「%2」を使用しています（%3、%4）。</translation>
    </message>
</context>
<context>
    <name>SystemEditor::SystemCanvas</name>
    <message>
        <location filename="../../systemeditor/widgets/systemcanvas.cpp" line="+36"/>
        <source>Find component by instance name</source>
        <translation>インスタンス名でコンポーネントを検索</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Close</source>
        <translation>閉じる</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Find:</source>
        <translation>検索：</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>&amp;Delete</source>
        <translation>削除(&amp;D)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Copy</source>
        <translation>コピー(&amp;C)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Paste</source>
        <translation>貼り付け(&amp;P)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Select &amp;All</source>
        <translation>すべて選択(&amp;A)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Rename Instance</source>
        <translation>インスタンス名を変更(&amp;R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Group as Composite…</source>
        <translation>複合コンポーネントにまとめる(&amp;G)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>D&amp;ecompose</source>
        <translation>分解(&amp;E)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Find Component…</source>
        <translation>コンポーネントを検索(&amp;F)…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Zoom &amp;In</source>
        <translation>ズームイン(&amp;I)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom &amp;Out</source>
        <translation>ズームアウト(&amp;O)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Actual Size</source>
        <translation>実際のサイズ(&amp;A)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Fit Diagram</source>
        <translation>ダイアグラム全体を表示(&amp;F)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Snap to &amp;Grid</source>
        <translation>グリッドにスナップ(&amp;G)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Face &amp;Right</source>
        <translation>右向き(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Face &amp;Left</source>
        <translation>左向き(&amp;L)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Face &amp;Up</source>
        <translation>上向き(&amp;U)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Face &amp;Down</source>
        <translation>下向き(&amp;D)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Align &amp;Left Edges</source>
        <translation>左端を揃える(&amp;L)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align &amp;Right Edges</source>
        <translation>右端を揃える(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align &amp;Top Edges</source>
        <translation>上端を揃える(&amp;T)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align &amp;Bottom Edges</source>
        <translation>下端を揃える(&amp;B)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align &amp;Centres Horizontally</source>
        <translation>水平方向の中央を揃える(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align Centres &amp;Vertically</source>
        <translation>垂直方向の中央を揃える(&amp;V)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Auto &amp;Layout</source>
        <translation>自動レイアウト(&amp;L)</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>&amp;Direction</source>
        <translation>向き(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;lign</source>
        <translation>整列(&amp;L)</translation>
    </message>
    <message numerus="yes">
        <location line="+24"/>
        <source>Grouped %n component(s) as %1.</source>
        <translation>
            <numerusform>%n個のコンポーネントを%1にまとめました。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Nothing to lay out.</source>
        <translation>レイアウトするものがありません。</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>Laid out %n component(s).</source>
        <translation>
            <numerusform>%n個のコンポーネントをレイアウトしました。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SystemEditor::SystemFile</name>
    <message>
        <location filename="../../systemeditor/systemfile.cpp" line="+78"/>
        <source>The RTC profile of %1 (%2) could not be read; its ports come from the system file.</source>
        <translation>%1（%2）のRTCプロファイルを読み込めませんでした。ポートはシステムファイルの情報を使用します。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The file is no RT system profile.</source>
        <translation>このファイルはRTSプロファイルではありません。</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>Cannot create the folder.</source>
        <translation>フォルダを作成できません。</translation>
    </message>
</context>
<context>
    <name>SystemEditor::SystemScene</name>
    <message>
        <location filename="../../systemeditor/scene/systemsceneedits.cpp" line="+51"/>
        <source>Delete</source>
        <translation>削除</translation>
    </message>
    <message numerus="yes">
        <location line="+81"/>
        <source>Decompose %n composites</source>
        <translation>
            <numerusform>%n個の複合コンポーネントを分解</numerusform>
        </translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Turn Components</source>
        <translation>コンポーネントの向きを変更</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>An instance name cannot be empty.</source>
        <translation>インスタンス名を空にすることはできません。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>There is already a component called &quot;%1&quot;.</source>
        <translation>「%1」という名前のコンポーネントはすでに存在します。</translation>
    </message>
    <message>
        <location filename="../../systemeditor/scene/systemsceneinteraction.cpp" line="+110"/>
        <source>Release to connect to %1</source>
        <translation>離すと%1に接続します</translation>
    </message>
</context>
<context>
    <name>SystemEditor::SystemView</name>
    <message>
        <location filename="../../systemeditor/widgets/systemview.cpp" line="+148"/>
        <source>No component matches &quot;%1&quot;.</source>
        <translation>「%1」に一致するコンポーネントはありません。</translation>
    </message>
    <message>
        <location filename="../../systemeditor/widgets/systemviewedits.cpp" line="+136"/>
        <source>Only RTC profiles can be dropped on a system.</source>
        <translation>システムにドロップできるのはRTCプロファイルだけです。</translation>
    </message>
</context>
<context>
    <name>SystemProfileInfo</name>
    <message>
        <location filename="../../systemeditor/systemprofileinfo.cpp" line="+56"/>
        <source>The %1 is empty.</source>
        <translation>%1が空です。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 must not contain &apos;:&apos;.</source>
        <translation>%1に「:」を含めることはできません。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>vendor</source>
        <translation>ベンダ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>system name</source>
        <translation>システム名</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>version</source>
        <translation>バージョン</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../../app/main.cpp" line="+40"/>
        <source>--export-diagram needs --output OUT.png or OUT.svg</source>
        <translation>--export-diagram には --output OUT.png または OUT.svg が必要です</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>IDE for OpenRTM-aist RT-Components and RT Systems.</source>
        <translation>OpenRTM-aistのRTコンポーネントとRTシステムのための統合開発環境です。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Render the diagram of a system file without a window.</source>
        <translation>ウィンドウを開かずにシステムファイルのダイアグラムを描画します。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where --export-diagram writes (.png or .svg).</source>
        <translation>--export-diagram の出力先（.png または .svg）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open a system, run it on the local runtime (started when needed) and show it online with its first connection in the Port Monitor.</source>
        <translation>システムを開いてローカルランタイム（必要なら起動）で実行し、オンラインで表示して最初の接続をポートモニタに表示します。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>RTC or RTS profiles to open (XML or YAML).</source>
        <translation>開くRTCプロファイルまたはRTSプロファイル（XMLまたはYAML）。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>TLS: %1</source>
        <translation>TLS: %1</translation>
    </message>
</context>
</TS>
