"""The IDTA 02021 template as published: its submodel's semanticId and each element's semanticId,
read from the template file stored in catalogs/idta-02021/ (its source in SOURCES.md there), so that
no identifier of the template is typed twice."""

from __future__ import annotations

import json
import re
from functools import lru_cache

from ..data.catalog import CATALOG_DIR

#: The template file stored, version 1.0.1 (metamodel V3.0 JSON); 1.0.2 changes the qualifiers'
#: kind, which an instance does not carry (readings I11).
TEMPLATE_FILE = CATALOG_DIR / "idta-02021" / "IDTA 02021-1-0-1_Template_Sizing of Power Drive Trains.json"
#: The submodel's semanticId as the template gives it.
SUBMODEL_SEMANTIC_ID = "https://admin-shell.io/idta/PowerDriveTrainSizing/1/0"
#: The numbering of an element the template allows more than once: ``MainComponent01`` (readings I5).
_NUMBER = re.compile(r"\d{2,}$")


def base_id_short(id_short: str) -> str:
    """An element's idShort without the number that tells several of one kind apart.

    Parameters
    ----------
    id_short : str
        ``MainComponent02``.

    Returns
    -------
    str
        ``MainComponent``.
    """
    return _NUMBER.sub("", id_short)


@lru_cache(maxsize=1)
def template_elements() -> dict:
    """Every element of the template's submodel by its idShort path.

    Returns
    -------
    dict
        ``"SizingResult.MainComponent.RmsOfMotorTorque"`` -> the element as JSON (a dict).
    """
    submodel = json.loads(TEMPLATE_FILE.read_text(encoding="utf-8"))["submodels"][0]
    out: dict = {}

    def walk(element: dict, prefix: str) -> None:
        path = prefix + element["idShort"]
        out[path] = element
        children = element.get("statements") if element["modelType"] == "Entity" else element.get("value")
        if isinstance(children, list) and element["modelType"] != "MultiLanguageProperty":
            for child in children:
                walk(child, path + ".")

    for element in submodel["submodelElements"]:
        walk(element, "")
    return out


def semantic_id(path: str) -> tuple[str, str, str]:
    """The semanticId of a template element.

    Parameters
    ----------
    path : str
        The element's idShort path in the template, ``SizingResult.MainComponent.RmsOfMotorTorque``.

    Returns
    -------
    tuple of str
        The reference's type, its key's type and its key's value, as the template writes them.
    """
    ref = template_elements()[path]["semanticId"]
    key = ref["keys"][0]
    return ref["type"], key["type"], key["value"]
