"""The documents the formulas cite, each declared once (:class:`calc.core.citation.Document`).

Every formula of the package names its source as citations of these (:class:`calc.core.citation.Source`);
the tests hold every formula to a document of :data:`DOCUMENTS` and every document to some formula.
An address is given only where the project's reference data gives one; none of these has one.
"""

from __future__ import annotations

from ..core.citation import Citation, Document

#: The engineering guide the project implements.
SOURCE = Document(
    "source",
    "a distributor's selection guide, without a title of its own: Determination of the Duty Cycle (ED); Selection of "
    "Optimum Gearbox for a Continuous Operation (S1); Selection of Optimum Gearbox for a Cycle Operation (S5); Sizing "
    "and Selecting for Couplings and Safety Couplings; Accuracy in Gearboxes and Couplings: Definitions",
    "a gearbox distributor, not named in the text",
    edition="the text as received, its figures lost to the conversion (only their captions remain)",
    held="its words beside each reading: notebook 13-source-and-errata",
)
#: Where the source is garbled or silent, the reading the project takes (E1 to E16).
ERRATA = Document(
    "errata",
    "Errata and readings of the source document",
    "drivetrain-calc (this project)",
    edition="E1 to E16",
    held="calc/report/errata.toml, one line per reading, as the calc report lists them; notebook 13-source-and-errata",
    joiner=" ",
)
#: The project's case file and results, with the readings of the motion, the motor's side and its ratings.
CASE_FORMAT = Document(
    "case format",
    "Design case file and results: the interface contract",
    "drivetrain-calc (this project)",
    held="docs/case-format.md",
)
#: Results any textbook of mechanics gives.
MECHANICS = Document(
    "mechanics",
    "textbook mechanics and geometry: the circle, torque and power, rigid bodies, torsional vibration",
    "standard results, derived where they are used (no one book)",
)
DUBBEL = Document("Dubbel", "Dubbel, Taschenbuch für den Maschinenbau", "Springer")
RW_ZA = Document(
    "R+W ZA line shaft catalog", "ZA line shafts (catalogue)", "R+W", held="catalogs/couplings.csv, row ZA-150"
)
RW_EK = Document("R+W sizing of elastomer couplings EK", "elastomer couplings EK (catalogue): sizing", "R+W")
KTR_ROTEX = Document("KTR ROTEX coupling selection", "ROTEX couplings (catalogue): coupling selection", "KTR")
MAYR_ROBA_ES = Document(
    "Mayr ROBA-ES B.9.6.EN",
    "Installation and Operational Instructions for ROBA-ES couplings Type 94_._ _ _._ sizes 14 to 65",
    "Mayr",
    edition="B.9.6.EN (11/03/2022)",
    held="catalogs/factors/starts-roba-es.csv and temperature-roba-es.csv",
    joiner=" ",
)
WITTENSTEIN = Document("WITTENSTEIN alpha catalogues", "alpha gearbox catalogues", "WITTENSTEIN alpha")
HARMONIC_DRIVE = Document(
    "Harmonic Drive engineering data (HFUC, CSF, CSG)",
    "engineering data of the HFUC, CSF and CSG strain wave gears",
    "Harmonic Drive",
)
#: The drive makers' sizing chapters the servo drive's methods follow.
DRIVE_SIZING = Document(
    "drive makers' sizing chapters",
    "sizing of servo drives, brake resistors and multi-axis DC buses (installation and selection manuals)",
    "Kollmorgen (AKD, S700), Yaskawa (Σ-7), Mitsubishi Electric (MR-J4), Schneider Electric (Motion Sizer), Beckhoff",
    held="catalogs/drives.csv, its source column for each row",
)

#: The registry: every document a formula may cite.
DOCUMENTS = (SOURCE, ERRATA, CASE_FORMAT, MECHANICS, DUBBEL, RW_ZA, RW_EK, KTR_ROTEX, MAYR_ROBA_ES, WITTENSTEIN,
             HARMONIC_DRIVE, DRIVE_SIZING)


def motion_reading(says: str = "") -> Citation:
    """The case format's motion and mechanism, read by the project (the load cycle derived from moves).

    Parameters
    ----------
    says : str
        What the reading takes, in words; empty for the reading alone.

    Returns
    -------
    Citation
        ``a reading (spec, Motion and mechanism): says``.
    """
    return CASE_FORMAT.at("Motion and mechanism: the load cycle derived instead of typed",
                          says=says, label="a reading (spec, Motion and mechanism)")
