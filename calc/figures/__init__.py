"""The figures of the domain (matplotlib) and the glossary of the formulas' symbols, drawn from
results, never computing them again."""
