"""Ablations of a shipped rule file, for tests that show what a rule or a
tagged condition fixes: the same text with it left out."""

from hexbot.planning.locomotion.scenarios import _data


def shipped(name: str) -> str:
    """The text of the shipped rule set ``name`` (e.g. "salvador")."""
    return _data("rulesets", ".rules")[name].read_text()


def without_tag(text: str, tag: str) -> str:
    """``text`` with every line marked ``# TAG`` left out."""
    lines = [ln for ln in text.splitlines() if not ln.rstrip().endswith(f"# {tag}")]
    assert len(lines) < len(text.splitlines()), f"no line is tagged {tag}"
    return "\n".join(lines)


def without_rule(text: str, name: str) -> str:
    """``text`` without the rule ``name`` (its header down to the next blank line)."""
    out, skip = [], False
    for line in text.splitlines():
        if line.startswith(f"rule {name} "):
            skip = True
        elif skip and not line.strip():
            skip = False
            continue
        if not skip:
            out.append(line)
    assert len(out) < len(text.splitlines()), f"no rule {name}"
    return "\n".join(out)
