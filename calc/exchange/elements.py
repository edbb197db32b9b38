"""The AAS elements of the submodel, built with aas-core3.0 from the template's own identifiers
(:mod:`calc.exchange.template`): a property, a file, a text, a collection, an entity."""

from __future__ import annotations

import aas_core3.stringification as strings
import aas_core3.types as aas

from .. import Q_
from .template import semantic_id


def reference(ref_type: str, key_type: str, value: str) -> aas.Reference:
    """A reference of one key.

    Parameters
    ----------
    ref_type, key_type : str
        As the JSON writes them: ``ExternalReference``, ``GlobalReference``.
    value : str
        The key's value.

    Returns
    -------
    aas_core3.types.Reference
    """
    return aas.Reference(strings.reference_types_from_str(ref_type),
                         [aas.Key(strings.key_types_from_str(key_type), value)])


def template_reference(path: str) -> aas.Reference:
    """The semanticId of a template element, as the template gives it.

    Parameters
    ----------
    path : str
        The element's idShort path in the template.

    Returns
    -------
    aas_core3.types.Reference
    """
    return reference(*semantic_id(path))


def number(path: str, value, unit: str | None = None, id_short: str | None = None) -> aas.Property | None:
    """A number of the template as ``xs:double`` (readings I1), in the template's unit.

    Parameters
    ----------
    path : str
        The element's idShort path in the template.
    value : dict, float or None
        A result as the JSON writes it (``{"value": 1.2, "unit": "N*m"}``) or a bare number.
    unit : str, optional
        The template's unit, into which a result with a unit is converted.
    id_short : str, optional
        The idShort, where not the template's.

    Returns
    -------
    aas_core3.types.Property or None
        None where there is no value.
    """
    if isinstance(value, dict):
        if value.get("value") is None:
            return None
        value = Q_(value["value"], value["unit"] or "").m_as(unit or "")
    if value is None:
        return None
    return aas.Property(aas.DataTypeDefXSD.DOUBLE, id_short=id_short or path.rsplit(".", 1)[-1],
                        semantic_id=template_reference(path), value=repr(float(value)))


def text(path: str, value: str | None, id_short: str | None = None,
         value_type: aas.DataTypeDefXSD = aas.DataTypeDefXSD.STRING) -> aas.Property | None:
    """A string property of the template.

    Parameters
    ----------
    path : str
        The element's idShort path in the template.
    value : str or None
        Its value; None leaves the property out.
    id_short : str, optional
        The idShort, where not the template's.
    value_type : aas_core3.types.DataTypeDefXSD, optional
        ``xs:string`` unless the template says otherwise (a date).

    Returns
    -------
    aas_core3.types.Property or None
    """
    if value is None:
        return None
    return aas.Property(value_type, id_short=id_short or path.rsplit(".", 1)[-1],
                        semantic_id=template_reference(path), value=str(value))


def words(path: str, value: str, id_short: str | None = None) -> aas.MultiLanguageProperty:
    """A multi-language property of the template, in English.

    Parameters
    ----------
    path : str
        The element's idShort path in the template.
    value : str
        The English text.
    id_short : str, optional
        The idShort, where not the template's.

    Returns
    -------
    aas_core3.types.MultiLanguageProperty
    """
    return aas.MultiLanguageProperty(id_short=id_short or path.rsplit(".", 1)[-1],
                                     semantic_id=template_reference(path),
                                     value=[aas.LangStringTextType("en", value)])


def file(path: str, value: str, content_type: str, id_short: str | None = None,
         sha256: str | None = None) -> aas.File:
    """A file element of the template, with the file's SHA-256 as an extension where given.

    Parameters
    ----------
    path : str
        The element's idShort path in the template.
    value : str
        The file's path: in an AASX, inside the package (``/aasx/files/case.toml``).
    content_type : str
        Its MIME type.
    id_short : str, optional
        The idShort, where not the template's.
    sha256 : str, optional
        The file's SHA-256, hexadecimal.

    Returns
    -------
    aas_core3.types.File
    """
    extensions = [aas.Extension("SHA-256", value_type=aas.DataTypeDefXSD.STRING, value=sha256)] if sha256 else None
    return aas.File(content_type, extensions=extensions, id_short=id_short or path.rsplit(".", 1)[-1],
                    semantic_id=template_reference(path), value=value)


def collection(path: str, children: list, id_short: str | None = None) -> aas.SubmodelElementCollection | None:
    """A collection of the template holding the children that have a value.

    Parameters
    ----------
    path : str
        The element's idShort path in the template.
    children : list
        Elements or None (left out).
    id_short : str, optional
        The idShort, where not the template's.

    Returns
    -------
    aas_core3.types.SubmodelElementCollection or None
        None where no child has a value.
    """
    kept = [c for c in children if c is not None]
    if not kept:
        return None
    return aas.SubmodelElementCollection(id_short=id_short or path.rsplit(".", 1)[-1],
                                         semantic_id=template_reference(path), value=kept)


def entity(path: str, statements: list, id_short: str | None = None,
           global_asset_id: str | None = None) -> aas.Entity:
    """An entity of the template: co-managed, or self-managed where it names its asset.

    Parameters
    ----------
    path : str
        The element's idShort path in the template.
    statements : list
        Elements or None (left out).
    id_short : str, optional
        The idShort, where not the template's.
    global_asset_id : str, optional
        The asset of a self-managed entity.

    Returns
    -------
    aas_core3.types.Entity
    """
    kind = aas.EntityType.SELF_MANAGED_ENTITY if global_asset_id else aas.EntityType.CO_MANAGED_ENTITY
    return aas.Entity(kind, id_short=id_short or path.rsplit(".", 1)[-1], semantic_id=template_reference(path),
                      statements=[s for s in statements if s is not None] or None,
                      global_asset_id=global_asset_id)
