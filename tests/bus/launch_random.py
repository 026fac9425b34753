"""Seeded random launch files: nested groups and includes with arguments, remappings,
parameters, ``<env>``, ``<rosparam>`` and nodes, for comparing loaders.

:func:`random_case` writes one top-level file and the files it includes into a folder and
returns the top file and the command-line arguments to give it. Most cases are valid;
a few are not on purpose (an argument passed to an include that does not declare it, an
``<arg>`` set twice, an unset argument used), so refusals are compared too.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from pathlib import Path
from xml.sax.saxutils import quoteattr

WORDS = ("alpha", "beta", "gamma", "delta", "base_link", "odom", "scan", "cmd_vel")
VALUES = (
    "1",
    "2.5",
    "-3",
    "true",
    "False",
    "text",
    "1e3",
    "0x10",
    "007",
    " padded ",
    "a b",
    "1_000",
)
YAML_VALUES = ("1", "2.5", "[1, 2, 3]", "{x: 1, y: [a, b]}", "!degrees 90", "deg(45)")
YAML_VALUES += ("rad(pi/4)", "!radians 2*pi", "'quoted'", "true", "~", "1.0e-3")


@dataclass
class _Scope:
    args: dict[str, str]  # name -> a literal value it is known to hold (numbers as text)
    flags: list[str] = field(default_factory=list)  # args holding true/false
    fixed: list[str] = field(default_factory=list)  # args with value= (not settable)


class _Writer:
    def __init__(self, rng: random.Random, folder: Path) -> None:
        self.rng = rng
        self.folder = folder
        self.counter = 0
        self.files = 0

    def unique(self, prefix: str) -> str:
        self.counter += 1
        return f"{prefix}{self.counter}"

    def value(self, scope: _Scope) -> str:
        rng = self.rng
        choice = rng.random()
        if scope.args and choice < 0.3:
            return f"$(arg {rng.choice(sorted(scope.args))})"
        if choice < 0.4:
            return (
                f"$(optenv WB_RANDOM_{rng.randint(0, 2)} {rng.choice(WORDS)}  {rng.choice(WORDS)})"
            )
        if choice < 0.45:
            return f"$(anon {rng.choice(WORDS)})"
        if choice < 0.5:
            return "$(dirname)/data.yaml"
        numbers = [a for a, v in scope.args.items() if v.lstrip("-").isdigit()]
        if numbers and choice < 0.6:
            return f"$(eval {rng.choice(numbers)} * {rng.randint(1, 5)} + {rng.randint(0, 9)})"
        if scope.flags and choice < 0.65:
            return f"$(eval 'on' if {rng.choice(scope.flags)} else 'off')"
        return rng.choice(VALUES) + ("_" + rng.choice(WORDS) if rng.random() < 0.2 else "")

    def condition(self, scope: _Scope) -> str:
        rng = self.rng
        if not rng.random() < 0.3:
            return ""
        kind = rng.choice(("if", "unless"))
        if scope.flags and rng.random() < 0.6:
            flag = rng.choice(scope.flags)
            text = f"$(arg {flag})" if rng.random() < 0.5 else f"$(eval not {flag})"
        else:
            text = rng.choice(("true", "false", "1", "0", "True"))
        return f" {kind}={quoteattr(text)}"

    def yaml_block(self) -> str:
        rng = self.rng
        lines = []
        for _ in range(rng.randint(1, 4)):
            lines.append(f"{rng.choice(WORDS)}_{rng.randint(0, 3)}: {rng.choice(YAML_VALUES)}")
        if rng.random() < 0.3:
            lines.append(f"{rng.choice(WORDS)}: {{inner: {rng.choice(YAML_VALUES)}}}")
        return "\n".join(lines)

    def node(self, scope: _Scope, depth: int, test: bool = False) -> str:
        rng = self.rng
        name = self.unique("n")
        attrs = f' pkg="pkg_{rng.randint(0, 3)}" type="{rng.choice(WORDS)}_node"'
        if test:
            attrs = f' test-name="{name}_test"' + attrs
            if rng.random() < 0.5:
                attrs += f' name="{name}"'
            if rng.random() < 0.3:
                attrs += f' time-limit="{rng.choice(("30", "12.5"))}"'
        else:
            attrs += f' name="{name}"'
            if rng.random() < 0.3:
                attrs += f' respawn="{rng.choice(("true", "false", "TRUE"))}"'
                attrs += f' respawn_delay="{rng.choice(("0", "1.5", "3"))}"'
            elif rng.random() < 0.2:
                attrs += ' required="true"'
            if rng.random() < 0.3:
                attrs += f' output="{rng.choice(("screen", "log"))}"'
        if rng.random() < 0.3:
            attrs += f' ns="{rng.choice(("sub", "/abs", "a/b"))}"'
        if rng.random() < 0.4:
            word = self.value(scope)
            word = word if not word.startswith("$(eval") else "eval_free"
            attrs += f" args={quoteattr(word + ' --flag ' + repr('x y'))}"
        if rng.random() < 0.15:
            attrs += f' cwd="{rng.choice(("node", "ROS_HOME", "ros_home"))}"'
        if rng.random() < 0.15:
            attrs += ' launch-prefix="nice -n 5"'
        if rng.random() < 0.15:
            attrs += ' clear_params="true"'
        attrs += self.condition(scope)
        body = []
        for _ in range(rng.randint(0, 4)):
            kind = rng.random()
            if kind < 0.35:
                pname = rng.choice(("p", "~q", "/g", "deep/er"))
                body.append(
                    f"<param name={quoteattr(pname)} value={quoteattr(self.value(scope))}/>"
                )
            elif kind < 0.55:
                source, target = rng.choice(WORDS), rng.choice(WORDS)
                body.append(f'<remap from="{source}" to="/{target}"/>')
            elif kind < 0.7:
                body.append(
                    f'<env name="E{rng.randint(0, 2)}" value={quoteattr(self.value(scope))}/>'
                )
            else:
                ns = f' ns="{rng.choice(WORDS)}"' if rng.random() < 0.5 else ""
                body.append(f"<rosparam{ns}>\n{self.yaml_block()}\n</rosparam>")
        tag = "test" if test else "node"
        return f"<{tag}{attrs}>\n" + "\n".join(body) + f"\n</{tag}>"

    def arg(self, scope: _Scope) -> str:
        rng = self.rng
        name = self.unique("a")
        kind = rng.random()
        if kind < 0.15 and scope.args:
            source = rng.choice(sorted(scope.args))
            text, known = f"$(arg {source})", scope.args[source]
            if source in scope.flags:
                scope.flags.append(name)
        elif kind < 0.4:
            text = known = rng.choice(("true", "false"))
            scope.flags.append(name)
        elif kind < 0.7:
            text = known = str(rng.randint(-3, 9))
        else:
            text = known = rng.choice(WORDS)
        doc = f" doc={quoteattr('the ' + name)}" if rng.random() < 0.3 else ""
        fixed = rng.random() < 0.2
        if fixed:
            scope.fixed.append(name)
        scope.args[name] = known
        return f'<arg name="{name}" {"value" if fixed else "default"}={quoteattr(text)}{doc}/>'

    def body(self, scope: _Scope, depth: int, top: bool) -> list[str]:
        rng = self.rng
        out: list[str] = []
        for _ in range(rng.randint(3, 9)):
            kind = rng.random()
            if kind < 0.2:
                out.append(self.arg(scope))
            elif kind < 0.35:
                name = rng.choice(("p", "~priv", "/glob", "ns/p", "t"))
                typed = rng.random()
                if typed < 0.2:
                    out.append(
                        f'<param name="{self.unique(name)}" type="str" '
                        f"value={quoteattr(self.value(scope))}/>"
                    )
                elif typed < 0.3:
                    out.append(
                        f'<param name="{self.unique("y")}" type="yaml" value="{{a: [1, 2]}}"/>'
                    )
                else:
                    out.append(
                        f"<param name={quoteattr(self.unique(name))} value={quoteattr(self.value(scope))}{self.condition(scope)}/>"
                    )
            elif kind < 0.45:
                out.append(f'<remap from="{rng.choice(WORDS)}" to="{rng.choice(WORDS)}_{depth}"/>')
            elif kind < 0.5:
                out.append(
                    f'<env name="E{rng.randint(0, 2)}" value={quoteattr(self.value(scope))}/>'
                )
            elif kind < 0.6:
                extra = rng.random()
                if extra < 0.2:
                    out.append(f'<rosparam command="delete" param="{rng.choice(WORDS)}"/>')
                elif extra < 0.35:
                    out.append(
                        f'<rosparam param="{rng.choice(WORDS)}" subst_value="true">'
                        f"{self.value(scope)}</rosparam>"
                    )
                else:
                    ns = f' ns="{rng.choice(WORDS)}"' if rng.random() < 0.5 else ""
                    out.append(f"<rosparam{ns}>\n{self.yaml_block()}\n</rosparam>")
            elif kind < 0.75:
                out.append(self.node(scope, depth, test=rng.random() < 0.1))
            elif kind < 0.87 and depth > 0:
                inner = _Scope(dict(scope.args), list(scope.flags))
                ns = f' ns="{rng.choice(("g", "/top", "x/y"))}"' if rng.random() < 0.6 else ""
                clear = ' clear_params="true"' if ns and rng.random() < 0.2 else ""
                lines = self.body(inner, depth - 1, False)
                out.append(
                    f"<group{ns}{clear}{self.condition(scope)}>\n" + "\n".join(lines) + "\n</group>"
                )
            elif depth > 0 and self.files < 6:
                out.append(self.include(scope, depth - 1))
        return out

    def include(self, scope: _Scope, depth: int) -> str:
        rng = self.rng
        self.files += 1
        name = self.unique("inc") + ".launch"
        pass_all = rng.random() < 0.3
        child = _Scope({}, [])
        passed: list[str] = []
        declared_lines = []
        for arg in sorted(scope.args):  # the included file declares some of the includer's args
            if rng.random() < 0.4:
                passed.append(arg)
                declared_lines.append(f'<arg name="{arg}" default="dflt"/>')
                child.args[arg] = "dflt" if not pass_all else scope.args[arg]
        if pass_all:
            child = _Scope(dict(scope.args), list(scope.flags))
        body = self.body(child, depth, False)
        (self.folder / name).write_text(
            "<launch>\n" + "\n".join(declared_lines + body) + "\n</launch>\n"
        )
        lines = []
        for arg in passed:
            if not pass_all or rng.random() < 0.5:
                key = "default" if rng.random() < 0.3 else "value"
                lines.append(f'<arg name="{arg}" {key}="$(arg {arg})"{self.condition(scope)}/>')
        if rng.random() < 0.1:  # roslaunch ignores a <remap> here (with a warning)
            lines.append('<remap from="ignored" to="also_ignored"/>')
        if rng.random() < 0.05:  # roslaunch refuses an argument the file does not declare
            lines.append('<arg name="undeclared" value="1"/>')
        if rng.random() < 0.2:
            lines.append(f'<env name="INC_ENV" value="{rng.choice(WORDS)}"/>')
        attrs = f' file="$(dirname)/{name}"'
        if pass_all:
            attrs += ' pass_all_args="true"'
        if rng.random() < 0.4:
            attrs += f' ns="{rng.choice(("inc", "/abs_inc", "i/j"))}"'
        return f"<include{attrs}{self.condition(scope)}>\n" + "\n".join(lines) + "\n</include>"


def random_case(seed: int, folder: Path) -> tuple[Path, list[str]]:
    """Write case ``seed`` into ``folder``; the top file and its ``name:=value`` arguments."""
    rng = random.Random(seed)
    folder.mkdir(parents=True, exist_ok=True)
    writer = _Writer(rng, folder)
    scope = _Scope({})
    lines = writer.body(scope, depth=3, top=True)
    if rng.random() < 0.03:
        lines.append('<param name="unset" value="$(arg never_declared)"/>')
    top = folder / "top.launch"
    top.write_text("<launch>\n" + "\n".join(lines) + "\n</launch>\n")
    (folder / "data.yaml").write_text("k: 1\n")
    free = [name for name in sorted(scope.args) if name not in scope.fixed]
    given = [f"{name}:=given_{name}" for name in free[:1]]
    return top, given
