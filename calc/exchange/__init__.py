"""The sizing exchanged with the vendors' world: the case and its evaluated results as an IDTA 02021
"Sizing of Power Drive Trains" submodel (Asset Administration Shell, metamodel V3.0, JSON and AASX),
and a case file read back from such a submodel.

``template`` reads the published template the submodel follows, ``motion_file`` the motion
pattern's CSV, ``build`` fills the submodel from the results, ``package`` writes and reads the
AASX, ``reader`` turns a submodel into a case file. The readings of the template are in
docs/idta-02021-readings.md (cited as I1 ...).
"""

from pathlib import Path


def aasx_beside(case: Path) -> Path:
    """Where a case's AASX lies beside its case file: what the review page's save writes and the
    calc report's title block names when it is there.

    Parameters
    ----------
    case : pathlib.Path
        The case file.

    Returns
    -------
    pathlib.Path
        ``indexing-table.toml`` -> ``indexing-table.aasx`` in the same folder.
    """
    return Path(case).with_suffix(".aasx")
