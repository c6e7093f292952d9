"""The linter: CiA 306 structure, CiA 301 semantics, PDO and COB-ID rules with stable codes."""

from .config import Selection, load_selection
from .rules import RULES, Finding, Fix, LintOptions, Rule
from .runner import has_errors, lint

__all__ = ["RULES", "Finding", "Fix", "LintOptions", "Rule", "Selection", "has_errors", "lint", "load_selection"]
