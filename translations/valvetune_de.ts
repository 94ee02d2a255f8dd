<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>vt::app::MainWindow</name>
    <message>
        <source>ValveTune</source>
        <translation>ValveTune</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Device</source>
        <translation>&amp;Gerät</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;New…</source>
        <translation>&amp;Neu…</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation>&amp;Verbinden…</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>&amp;Read All</source>
        <translation>Alle &amp;lesen</translation>
    </message>
    <message>
        <source>&amp;Write Changes…</source>
        <translation>Änderungen &amp;schreiben…</translation>
    </message>
    <message>
        <source>&amp;Scan Node</source>
        <translation>Knoten &amp;abfragen</translation>
    </message>
    <message>
        <source>&amp;Fold Wizard…</source>
        <translation>&amp;Knoten-Assistent…</translation>
    </message>
    <message>
        <source>&amp;About ValveTune…</source>
        <translation>Ü&amp;ber ValveTune…</translation>
    </message>
    <message>
        <source>Not available in this version yet</source>
        <translation>In dieser Version noch nicht verfügbar</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>Monitor</translation>
    </message>
    <message>
        <source>Telegrams</source>
        <translation>Telegramme</translation>
    </message>
    <message>
        <source>The parameters of the connected device or the open file appear here.</source>
        <translation>Hier erscheinen die Parameter des verbundenen Geräts oder der geöffneten Datei.</translation>
    </message>
    <message>
        <source>Live values of the connected device are plotted here.</source>
        <translation>Hier werden die Live-Werte des verbundenen Geräts aufgezeichnet.</translation>
    </message>
    <message>
        <source>Every telegram sent and received is listed here.</source>
        <translation>Hier wird jedes gesendete und empfangene Telegramm aufgelistet.</translation>
    </message>
    <message>
        <source>No device connected and no parameter file open.</source>
        <translation>Kein Gerät verbunden und keine Parameterdatei geöffnet.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Clear List</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>vt::link</name>
    <message>
        <source>empty item (two commas in a row?)</source>
        <translation>leerer Eintrag (zwei Kommas hintereinander?)</translation>
    </message>
    <message>
        <source>expected key=value</source>
        <translation>erwartet Schlüssel=Wert</translation>
    </message>
    <message>
        <source>given twice</source>
        <translation>doppelt angegeben</translation>
    </message>
    <message>
        <source>probability must be a number between 0 and 1</source>
        <translation>Wahrscheinlichkeit muss eine Zahl zwischen 0 und 1 sein</translation>
    </message>
    <message>
        <source>delay must be whole milliseconds, 0 to 60000</source>
        <translation>Verzögerung muss ganze Millisekunden sein, 0 bis 60000</translation>
    </message>
    <message>
        <source>cut must be a whole number of frames</source>
        <translation>cut muss eine ganze Anzahl Telegramme sein</translation>
    </message>
    <message>
        <source>seed must be a whole number from 0 to 4294967295</source>
        <translation>seed muss eine ganze Zahl von 0 bis 4294967295 sein</translation>
    </message>
    <message>
        <source>cut and seed apply to both directions; drop the tx./rx. prefix</source>
        <translation>cut und seed gelten für beide Richtungen; das Präfix tx./rx. weglassen</translation>
    </message>
    <message>
        <source>unknown key (known: drop, corrupt, delay, cut, seed; drop, corrupt and delay may take a tx. or rx. prefix)</source>
        <translation>unbekannter Schlüssel (bekannt: drop, corrupt, delay, cut, seed; drop, corrupt und delay erlauben das Präfix tx. oder rx.)</translation>
    </message>
</context>
<context>
    <name>vt::link::CanLink</name>
    <message>
        <source>CAN socket %1 was closed and cannot be reopened</source>
        <translation>CAN-Socket %1 wurde geschlossen und kann nicht wieder geöffnet werden</translation>
    </message>
    <message>
        <source>CAN socket %1 is unusable: %2</source>
        <translation>CAN-Socket %1 ist unbrauchbar: %2</translation>
    </message>
    <message>
        <source>Cannot open CAN interface %1: SocketCAN is not available in this kernel (%2)</source>
        <translation>CAN-Schnittstelle %1 kann nicht geöffnet werden: SocketCAN ist in diesem Kernel nicht verfügbar (%2)</translation>
    </message>
    <message>
        <source>Cannot open CAN interface %1: %2</source>
        <translation>CAN-Schnittstelle %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>Cannot open CAN interface %1: no such network interface</source>
        <translation>CAN-Schnittstelle %1 kann nicht geöffnet werden: keine solche Netzwerkschnittstelle</translation>
    </message>
    <message>
        <source>CAN interface %1: transmit backlog overflow</source>
        <translation>CAN-Schnittstelle %1: Sendepuffer übergelaufen</translation>
    </message>
    <message>
        <source>CAN interface %1: short write (%2 bytes)</source>
        <translation>CAN-Schnittstelle %1: unvollständig geschrieben (%2 Bytes)</translation>
    </message>
    <message>
        <source>CAN interface %1: transmit queue stays full (bus off?)</source>
        <translation>CAN-Schnittstelle %1: Sendewarteschlange bleibt voll (Bus-off?)</translation>
    </message>
    <message>
        <source>CAN interface %1: write failed: %2</source>
        <translation>CAN-Schnittstelle %1: Schreiben fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>CAN interface %1: read failed: %2</source>
        <translation>CAN-Schnittstelle %1: Lesen fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>CAN interface %1: socket closed</source>
        <translation>CAN-Schnittstelle %1: Socket geschlossen</translation>
    </message>
</context>
<context>
    <name>vt::link::FaultLink</name>
    <message>
        <source>Fault injection cut the link after %1 frames</source>
        <translation>Die Fehlerinjektion hat die Verbindung nach %1 Telegrammen getrennt</translation>
    </message>
</context>
<context>
    <name>vt::link::FaultSpecError</name>
    <message>
        <source>fault spec: %1</source>
        <translation>Fehlerangabe: %1</translation>
    </message>
    <message>
        <source>fault spec item &apos;%1&apos;: %2</source>
        <translation>Fehlerangabe, Eintrag &apos;%1&apos;: %2</translation>
    </message>
</context>
<context>
    <name>vt::link::Link</name>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Verbinde…</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <source>Connection failed</source>
        <translation>Verbindung fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>vt::link::SerialWorker</name>
    <message>
        <source>Serial port %1 not found</source>
        <translation>Serielle Schnittstelle %1 nicht gefunden</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>Cannot apply %1 baud %2 to %3: %4</source>
        <translation>%1 Baud %2 kann nicht auf %3 eingestellt werden: %4</translation>
    </message>
    <message>
        <source>Cannot open %1: no file descriptor</source>
        <translation>%1 kann nicht geöffnet werden: kein Dateideskriptor</translation>
    </message>
    <message>
        <source>Write to %1 failed: %2</source>
        <translation>Schreiben auf %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Write to %1 timed out</source>
        <translation>Schreiben auf %1: Zeitüberschreitung</translation>
    </message>
    <message>
        <source>Read from %1 failed: %2</source>
        <translation>Lesen von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Serial port %1 was disconnected</source>
        <translation>Serielle Schnittstelle %1 wurde getrennt</translation>
    </message>
</context>
<context>
    <name>vt::link::SimLink</name>
    <message>
        <source>No simulator is attached to %1</source>
        <translation>An %1 ist kein Simulator angeschlossen</translation>
    </message>
</context>
<context>
    <name>vt::link::TcpLink</name>
    <message>
        <source>Connection to %1 timed out after %2 ms</source>
        <translation>Verbindung zu %1: Zeitüberschreitung nach %2 ms</translation>
    </message>
    <message>
        <source>Connection to %1 closed by the peer</source>
        <translation>Verbindung zu %1 von der Gegenstelle geschlossen</translation>
    </message>
    <message>
        <source>Connection to %1 failed: %2</source>
        <translation>Verbindung zu %1 fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>vt::model::Connection</name>
    <message>
        <source>a TCP connection needs a host and a port</source>
        <translation>eine TCP-Verbindung braucht Host und Port</translation>
    </message>
    <message>
        <source>CANopen node %1 is not 1..127</source>
        <translation>CANopen-Knoten %1 liegt nicht in 1..127</translation>
    </message>
    <message>
        <source>a CAN connection needs an interface (can0, vcan0 …)</source>
        <translation>eine CAN-Verbindung braucht eine Schnittstelle (can0, vcan0 …)</translation>
    </message>
    <message>
        <source>module address %1 is not 0..255</source>
        <translation>Moduladresse %1 liegt nicht in 0..255</translation>
    </message>
    <message>
        <source>the link closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
</context>
<context>
    <name>vt::model::DeviceAccess</name>
    <message>
        <source>not readable over %1</source>
        <translation>über %1 nicht lesbar</translation>
    </message>
</context>
<context>
    <name>vt::model::MonitorScheduler</name>
    <message>
        <source>incomplete answer</source>
        <translation>unvollständige Antwort</translation>
    </message>
</context>
<context>
    <name>vt::model::SampleStore</name>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>not a ValveTune sample file</source>
        <translation>keine ValveTune-Messwertdatei</translation>
    </message>
    <message>
        <source>longer than %1 bytes</source>
        <translation>länger als %1 Byte</translation>
    </message>
    <message>
        <source>a channel needs an id, a name and a unit</source>
        <translation>ein Kanal braucht eine Kennung, einen Namen und eine Einheit</translation>
    </message>
    <message>
        <source>more than %1 channels</source>
        <translation>mehr als %1 Kanäle</translation>
    </message>
    <message>
        <source>the column header does not match the channels</source>
        <translation>die Spaltenüberschrift passt nicht zu den Kanälen</translation>
    </message>
    <message>
        <source>the column header is missing</source>
        <translation>die Spaltenüberschrift fehlt</translation>
    </message>
    <message>
        <source>expected %1 columns</source>
        <translation>%1 Spalten erwartet</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a time</source>
        <translation>„%1“ ist keine Zeitangabe</translation>
    </message>
    <message>
        <source>more than %1 samples</source>
        <translation>mehr als %1 Messwerte</translation>
    </message>
    <message>
        <source>time goes backwards</source>
        <translation>die Zeit läuft rückwärts</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>vt::model::Session</name>
    <message>
        <source>The request queue is full</source>
        <translation>Die Auftragswarteschlange ist voll</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>The link %1 is not open</source>
        <translation>Die Verbindung %1 ist nicht offen</translation>
    </message>
    <message>
        <source>The request cannot be encoded for %1</source>
        <translation>Der Auftrag lässt sich für %1 nicht codieren</translation>
    </message>
    <message>
        <source>unsolicited</source>
        <translation>unaufgefordert</translation>
    </message>
    <message>
        <source>does not answer the request</source>
        <translation>beantwortet die Anfrage nicht</translation>
    </message>
    <message>
        <source>no valid frame (checksum error, corrupted or incomplete)</source>
        <translation>kein gültiger Rahmen (Prüfsummenfehler, verfälscht oder unvollständig)</translation>
    </message>
    <message numerus="yes">
        <source>No answer after %n attempt(s)</source>
        <translation>
            <numerusform>Keine Antwort nach %n Versuch</numerusform>
            <numerusform>Keine Antwort nach %n Versuchen</numerusform>
        </translation>
    </message>
    <message>
        <source>The link %1 was lost</source>
        <translation>Die Verbindung %1 ist abgerissen</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>refused by the device</source>
        <translation>vom Gerät abgelehnt</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>Verbindung verloren</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>cannot be encoded</source>
        <translation>nicht codierbar</translation>
    </message>
</context>
<context>
    <name>vt::model::SimEndpoint</name>
    <message>
        <source>expected FAMILY or FAMILY:MODULES, got &apos;%1&apos;</source>
        <translation>erwartet FAMILIE oder FAMILIE:MODULE, erhalten „%1“</translation>
    </message>
    <message>
        <source>module count &apos;%1&apos; is not 1..32</source>
        <translation>Modulanzahl „%1“ liegt nicht in 1..32</translation>
    </message>
    <message>
        <source>the built-in dictionaries do not load</source>
        <translation>die eingebauten Wörterbücher lassen sich nicht laden</translation>
    </message>
    <message>
        <source>unknown device family &apos;%1&apos;</source>
        <translation>unbekannte Gerätefamilie „%1“</translation>
    </message>
    <message>
        <source>%1 speaks HART only</source>
        <translation>%1 spricht nur HART</translation>
    </message>
    <message>
        <source>the simulator does not serve %1 over &apos;%2&apos;</source>
        <translation>der Simulator bedient %1 nicht über „%2“</translation>
    </message>
    <message>
        <source>%1 cannot be simulated over a PC link yet (DSP-408 needs PROFIBUS or CANopen)</source>
        <translation>%1 lässt sich über eine PC-Verbindung noch nicht simulieren (DSP-408 braucht PROFIBUS oder CANopen)</translation>
    </message>
</context>
<context>
    <name>vt::model::TelegramLog</name>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>device exception</source>
        <translation>Geräteausnahme</translation>
    </message>
    <message>
        <source>checksum error</source>
        <translation>Prüfsummenfehler</translation>
    </message>
    <message>
        <source>malformed</source>
        <translation>fehlerhaft</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>Zeitüberschreitung</translation>
    </message>
    <message>
        <source>unmatched</source>
        <translation>nicht zugeordnet</translation>
    </message>
    <message>
        <source>out</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>in</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>no reply: %1</source>
        <translation>keine Antwort: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n Byte</numerusform>
            <numerusform>%n Byte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>ValveTune telegram log: %n record(s)</source>
        <translation>
            <numerusform>ValveTune-Telegrammprotokoll: %n Eintrag</numerusform>
            <numerusform>ValveTune-Telegrammprotokoll: %n Einträge</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n older record(s) dropped</source>
        <translation>
            <numerusform>%n älterer Eintrag verworfen</numerusform>
            <numerusform>%n ältere Einträge verworfen</numerusform>
        </translation>
    </message>
    <message>
        <source>module %1</source>
        <translation>Modul %1</translation>
    </message>
</context>
<context>
    <name>vt::model::TelegramLogModel</name>
    <message>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>Richt.</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
</context>
<context>
    <name>vt::model::TelegramRecorder</name>
    <message>
        <source>no answer to attempt %1</source>
        <translation>keine Antwort auf Versuch %1</translation>
    </message>
</context>
<context>
    <name>vt::model::WriteJob</name>
    <message>
        <source>unknown parameter</source>
        <translation>unbekannter Parameter</translation>
    </message>
    <message>
        <source>%1 expects %2</source>
        <translation>%1 erwartet %2</translation>
    </message>
    <message>
        <source>text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>eine Zahl</translation>
    </message>
    <message>
        <source>%1 is not writable</source>
        <translation>%1 ist nicht beschreibbar</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>acknowledged; not read back</source>
        <translation>bestätigt; nicht zurückgelesen</translation>
    </message>
    <message>
        <source>sent, but no answer (%1): the value may or may not be on the device</source>
        <translation>gesendet, aber keine Antwort (%1): der Wert ist möglicherweise im Gerät, möglicherweise nicht</translation>
    </message>
    <message>
        <source>read back %1, expected %2</source>
        <translation>zurückgelesen %1, erwartet %2</translation>
    </message>
    <message>
        <source>acknowledged; the read back failed (%1)</source>
        <translation>bestätigt; das Zurücklesen schlug fehl (%1)</translation>
    </message>
    <message>
        <source>found on the device after the interruption</source>
        <translation>nach der Unterbrechung im Gerät vorgefunden</translation>
    </message>
    <message>
        <source>not sent: the write stopped (%1)</source>
        <translation>nicht gesendet: das Schreiben wurde beendet (%1)</translation>
    </message>
    <message>
        <source>pending</source>
        <translation>ausstehend</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unverändert</translation>
    </message>
    <message>
        <source>refused before sending</source>
        <translation>vor dem Senden abgelehnt</translation>
    </message>
    <message>
        <source>verified</source>
        <translation>geprüft</translation>
    </message>
    <message>
        <source>written, not verified</source>
        <translation>geschrieben, nicht geprüft</translation>
    </message>
    <message>
        <source>refused by the device</source>
        <translation>vom Gerät abgelehnt</translation>
    </message>
    <message>
        <source>read back differs</source>
        <translation>Rücklesewert weicht ab</translation>
    </message>
    <message>
        <source>uncertain</source>
        <translation>ungewiss</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>nicht gesendet</translation>
    </message>
</context>
<context>
    <name>vt::ui::AboutDialog</name>
    <message>
        <source>About ValveTune</source>
        <translation>Über ValveTune</translation>
    </message>
    <message>
        <source>ValveTune %1

Parameterisation, tuning and commissioning of hydraulic proportional-valve electronics: HCS OPAT and DMA-2, Wandfluh ED1/SD1 (DSP-408) and SD7 (HART-7).

Licensed under the GNU General Public License, version 3 or later. Plots use QCustomPlot (GPL-3.0).</source>
        <translation>ValveTune %1

Parametrierung, Optimierung und Inbetriebnahme von Elektroniken für hydraulische Proportionalventile: HCS OPAT und DMA-2, Wandfluh ED1/SD1 (DSP-408) und SD7 (HART-7).

Lizenziert unter der GNU General Public License, Version 3 oder später. Die Diagramme verwenden QCustomPlot (GPL-3.0).</translation>
    </message>
</context>
</TS>
