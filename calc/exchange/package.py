"""Writing and reading the exchanged files: the environment as AAS JSON (metamodel V3.0) with its
files beside it, or as an AASX package (Open Packaging Conventions, the relationships of AAS part 5)
holding the JSON and the files; each written only after the meta-model's verification finds no
error, each read with one sentence for what is wrong."""

from __future__ import annotations

import json
import posixpath
import zipfile
from pathlib import Path, PurePosixPath
from xml.etree import ElementTree

import aas_core3.jsonization as jsonization
import aas_core3.types as aas
import aas_core3.verification as verification

from ..core.errors import CalcError
from .build import FILES, Exported

#: The relationship types of an AASX (AAS part 5).
ORIGIN = "http://admin-shell.io/aasx/relationships/aasx-origin"
SPEC = "http://admin-shell.io/aasx/relationships/aas-spec"
SUPPLEMENTARY = "http://admin-shell.io/aasx/relationships/aas-suppl"
_RELS = "http://schemas.openxmlformats.org/package/2006/relationships"
_TYPES = "http://schemas.openxmlformats.org/package/2006/content-types"
#: The environment's JSON inside the package.
SPEC_PART = "/aasx/sizing/sizing.aas.json"
#: The most bytes read of an AAS file or of a package's unpacked parts together.
MAX_BYTES = 200_000_000


def verified_json(environment: aas.Environment) -> str:
    """The environment as JSON text, after the meta-model's verification finds no error.

    Parameters
    ----------
    environment : aas_core3.types.Environment

    Returns
    -------
    str

    Raises
    ------
    CalcError
        Naming the first error the verification finds (a defect of the export, never of a case).
    """
    for error in verification.verify(environment):
        raise CalcError(f"the AAS export does not pass the meta-model's verification: {error.path}: {error.cause}")
    return json.dumps(jsonization.to_jsonable(environment), indent=2, ensure_ascii=False)


def write_json(exported: Exported, out: Path) -> list[Path]:
    """Write the environment as AAS JSON and the files its elements name beside it.

    Parameters
    ----------
    exported : calc.exchange.build.Exported
    out : pathlib.Path
        The JSON file.

    Returns
    -------
    list of pathlib.Path
        The files written, the JSON first.
    """
    out = Path(out)
    text = verified_json(exported.environment)
    written = [out]
    out.write_text(text, encoding="utf-8")
    for name, (_, data) in exported.files.items():
        if name.endswith(".csv"):  # the case file and report stay where they are
            (out.parent / name).write_bytes(data)
            written.append(out.parent / name)
    return written


def _relationships(targets: list[tuple[str, str]]) -> bytes:
    root = ElementTree.Element("Relationships", xmlns=_RELS)
    for k, (kind, target) in enumerate(targets, start=1):
        ElementTree.SubElement(root, "Relationship", Type=kind, Target=target, Id=f"R{k}")
    return ElementTree.tostring(root, xml_declaration=True, encoding="utf-8")


def write_aasx(exported: Exported, out: Path) -> Path:
    """Write the environment and its files as an AASX package.

    Parameters
    ----------
    exported : calc.exchange.build.Exported
        Built with ``in_package=True``.
    out : pathlib.Path
        The AASX file.

    Returns
    -------
    pathlib.Path
        ``out``.
    """
    text = verified_json(exported.environment)
    types = ElementTree.Element("Types", xmlns=_TYPES)
    for ext, mime in (("rels", "application/vnd.openxmlformats-package.relationships+xml"),
                      ("json", "application/json"), ("xml", "application/xml"), ("csv", "text/csv"),
                      ("toml", "application/toml"), ("pdf", "application/pdf")):
        ElementTree.SubElement(types, "Default", Extension=ext, ContentType=mime)
    ElementTree.SubElement(types, "Override", PartName="/aasx/aasx-origin", ContentType="text/plain")
    spec_dir, spec_name = posixpath.split(SPEC_PART)
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("[Content_Types].xml", ElementTree.tostring(types, xml_declaration=True, encoding="utf-8"))
        z.writestr("_rels/.rels", _relationships([(ORIGIN, "/aasx/aasx-origin")]))
        z.writestr("aasx/aasx-origin", "Intentionally empty.")
        z.writestr("aasx/_rels/aasx-origin.rels", _relationships([(SPEC, SPEC_PART)]))
        z.writestr(SPEC_PART.lstrip("/"), text)
        z.writestr(f"{spec_dir.lstrip('/')}/_rels/{spec_name}.rels",
                   _relationships([(SUPPLEMENTARY, FILES + name) for name in exported.files]))
        for name, (_, data) in exported.files.items():
            z.writestr((FILES + name).lstrip("/"), data)
    return Path(out)


class Opened:
    """An AAS file opened: its environment and a way to read the files its elements name.

    Parameters
    ----------
    path : pathlib.Path
        The JSON or AASX file.
    environment : aas_core3.types.Environment
    parts : dict or None
        An AASX's parts by name (``aasx/files/x.csv``); None for a JSON file, whose files lie beside it.
    """

    def __init__(self, path: Path, environment: aas.Environment, parts: dict | None):
        self.path, self.environment, self.parts = Path(path), environment, parts

    def read(self, reference: str, where: str) -> bytes:
        """The bytes of a file an element names.

        Parameters
        ----------
        reference : str
            The File element's value.
        where : str
            The element, as the error names it.

        Returns
        -------
        bytes

        Raises
        ------
        CalcError
            For a path that leaves the package (or the JSON file's folder) or a file not there.
        """
        if self.parts is not None:
            name = posixpath.normpath(reference.lstrip("/"))
            if ".." in PurePosixPath(reference).parts or name not in self.parts:
                raise CalcError(f"{self.path}: {where}: expected a file inside the package, found '{reference[:80]}'")
            return self.parts[name]
        folder = self.path.parent.resolve()
        target = (folder / reference).resolve()
        if folder not in target.parents or not target.is_file():
            raise CalcError(f"{self.path}: {where}: expected a file beside the AAS file, found '{reference[:80]}'")
        return target.read_bytes()


def open_aas(path: Path) -> Opened:
    """Open an AAS JSON file or AASX package.

    Parameters
    ----------
    path : pathlib.Path
        A ``.json`` or ``.aasx`` file.

    Returns
    -------
    Opened

    Raises
    ------
    CalcError
        For a file that is not there, not JSON, not a package, or not an AAS environment.
    """
    path = Path(path)
    if not path.is_file():
        raise CalcError(f"{path}: expected an AAS file (.json or .aasx), found no file")
    parts = None
    if path.suffix.lower() == ".aasx":
        parts = _package_parts(path)
        data = parts[_spec_name(path, parts)]
    else:
        if path.stat().st_size > MAX_BYTES:
            raise CalcError(f"{path}: expected an AAS file of at most {MAX_BYTES} bytes, found a larger one")
        data = path.read_bytes()
    try:
        jsonable = json.loads(data)
    except (ValueError, UnicodeDecodeError) as exc:
        raise CalcError(f"{path}: expected AAS JSON, found text that is not JSON ({str(exc)[:80]})") from None
    try:
        environment = jsonization.environment_from_jsonable(jsonable)
    except jsonization.DeserializationException as exc:
        raise CalcError(f"{path}: expected an AAS environment (metamodel V3.0), found at {exc.path}: "
                        f"{exc.cause[:120]}") from None
    return Opened(path, environment, parts)


def _package_parts(path: Path) -> dict:
    try:
        with zipfile.ZipFile(path) as z:
            if sum(i.file_size for i in z.infolist()) > MAX_BYTES:
                raise CalcError(f"{path}: expected a package of at most {MAX_BYTES} bytes unpacked, found more")
            return {i.filename: z.read(i) for i in z.infolist() if not i.is_dir()}
    except zipfile.BadZipFile:
        raise CalcError(f"{path}: expected an AASX package (a ZIP file), found a file that is not one") from None


def _spec_name(path: Path, parts: dict) -> str:
    def targets(rels_name: str, kind: str) -> list[str]:
        if rels_name not in parts:
            return []
        try:
            root = ElementTree.fromstring(parts[rels_name])
        except ElementTree.ParseError:
            return []
        return [r.get("Target", "") for r in root if r.get("Type") == kind]

    for origin in targets("_rels/.rels", ORIGIN):
        origin = origin.lstrip("/")
        folder, name = posixpath.split(origin)
        for spec in targets(posixpath.join(folder, "_rels", name + ".rels"), SPEC):
            name = posixpath.normpath(posixpath.join("/" + folder, spec)).lstrip("/")
            if name in parts and name.endswith(".json"):
                return name
    raise CalcError(f"{path}: expected an AASX whose origin names an AAS JSON part, found none")
