"""A typed view of the parse tree: one small class per node kind, with a named property for
each child, over the lark `Tree` the parser gives (as rust-analyzer's `ast` over `rowan`).

A view holds only its node (`syntax`); `Kind.cast(node)` gives the view, or None when the
node is of another kind, so code reads `Binary.cast(n)` rather than `n.children[1]` and the
shapes of glsl.lark are written down here once. Expressions and statements come back as raw
nodes (`Tree | Token`), to be passed on to walkers and evaluators; the typed parts of a
declaration (a prototype, its parameters, a type) come back as views.

The functions at the end (`callee_name`, `variable_name`, `for_parts` ...) read the same
shapes without building a view: the semantic model calls them by the hundred thousand.
"""

from __future__ import annotations

from typing import ClassVar, TypeVar

from lark import Token, Tree

Node = Tree | Token

_V = TypeVar("_V", bound="View")

# node kind -> its view class; `view(node)` looks a kind up, tests check every kind has one
VIEWS: dict[str, type[View]] = {}


class View:
    """A node of one of `KINDS`, seen through named properties."""

    __slots__ = ("syntax",)
    KINDS: ClassVar[tuple[str, ...]] = ()

    def __init__(self, syntax: Tree) -> None:
        self.syntax = syntax

    def __init_subclass__(cls) -> None:
        super().__init_subclass__()
        for kind in cls.KINDS:
            VIEWS[kind] = cls

    @classmethod
    def cast(cls: type[_V], node: object) -> _V | None:
        """The view of `node` when it is a node of this kind, else None."""
        if isinstance(node, Tree) and node.data in cls.KINDS:
            return cls(node)
        return None

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.syntax!r})"

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other.syntax is self.syntax  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return id(self.syntax)


def view(node: object) -> View | None:
    """The view of any node the parser builds (None for a token)."""
    if isinstance(node, Tree):
        cls = VIEWS.get(node.data)
        return cls(node) if cls is not None else None
    return None


def _tree(node: object, kind: str) -> Tree | None:
    return node if isinstance(node, Tree) and node.data == kind else None


def _first_tree(node: Tree, kind: str) -> Tree | None:
    for child in node.children:
        if isinstance(child, Tree) and child.data == kind:
            return child
    return None


def _first_token(node: Tree) -> Token | None:
    for child in node.children:
        if isinstance(child, Token):
            return child
    return None


# --- the file and functions ---------------------------------------------------------------


class SourceFile(View):
    """`start`: the file's external declarations and function definitions, in order."""

    __slots__ = ()
    KINDS = ("start",)

    @property
    def items(self) -> list[Tree]:
        return [c for c in self.syntax.children if isinstance(c, Tree)]

    @property
    def functions(self) -> list[FunctionDefinition]:
        return [
            FunctionDefinition(c)
            for c in self.syntax.children
            if isinstance(c, Tree) and c.data == "function_definition"
        ]


class FunctionDefinition(View):
    """`prototype { body }`"""

    __slots__ = ()
    KINDS = ("function_definition",)

    @property
    def prototype(self) -> FunctionPrototype:
        return FunctionPrototype(self.syntax.children[0])  # type: ignore[arg-type]

    @property
    def body(self) -> Tree:
        """The compound statement."""
        return self.syntax.children[1]  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return str(self.syntax.children[0].children[1])  # type: ignore[union-attr]


class FunctionPrototype(View):
    """`type name(parameters)`, alone (a declaration) or heading a definition."""

    __slots__ = ()
    KINDS = ("function_prototype",)

    @property
    def return_type(self) -> FullySpecifiedType:
        return FullySpecifiedType(self.syntax.children[0])  # type: ignore[arg-type]

    @property
    def name_token(self) -> Token:
        return self.syntax.children[1]  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return str(self.syntax.children[1])

    @property
    def parameter_list(self) -> ParameterList | None:
        kids = self.syntax.children
        return ParameterList(kids[2]) if len(kids) > 2 else None  # type: ignore[arg-type]

    @property
    def parameters(self) -> list[Parameter]:
        """The parameters; `f(void)` has one, unnamed, of type void."""
        kids = self.syntax.children
        if len(kids) < 3:
            return []
        return [Parameter(p) for p in kids[2].children if isinstance(p, Tree)]  # type: ignore[union-attr]


class ParameterList(View):
    __slots__ = ()
    KINDS = ("parameter_list",)

    @property
    def parameters(self) -> list[Parameter]:
        return [Parameter(p) for p in self.syntax.children if isinstance(p, Tree)]


class Parameter(View):
    """`[qualifiers] type [name [array]]`"""

    __slots__ = ()
    KINDS = ("parameter",)

    @property
    def qualifier(self) -> TypeQualifier | None:
        node = _first_tree(self.syntax, "type_qualifier")
        return TypeQualifier(node) if node is not None else None

    @property
    def type(self) -> TypeSpecifier:
        return TypeSpecifier(_first_tree(self.syntax, "type_specifier"))  # type: ignore[arg-type]

    @property
    def name_token(self) -> Token | None:
        return _first_token(self.syntax)

    @property
    def name(self) -> str | None:
        token = _first_token(self.syntax)
        return str(token) if token is not None else None

    @property
    def array(self) -> Tree | None:
        """The array specifier after the name (`float a[3]`), not the type's (`float[3] a`)."""
        return _first_tree(self.syntax, "array_specifier")

    @property
    def direction(self) -> str:
        """ "in", "out" or "inout"."""
        qualifier = self.qualifier
        if qualifier is not None:
            for word in qualifier.words:
                if word in ("in", "out", "inout"):
                    return word
        return "in"


# --- declarations and types ------------------------------------------------------------


class VariableDeclaration(View):
    """`type a = 1.0, b[2];`, or a bare `struct S { ... };` (no declarators)."""

    __slots__ = ()
    KINDS = ("variable_declaration",)

    @property
    def type(self) -> FullySpecifiedType:
        return FullySpecifiedType(self.syntax.children[0])  # type: ignore[arg-type]

    @property
    def declarators(self) -> list[Declarator]:
        return [Declarator(d) for d in self.syntax.children[1:]]  # type: ignore[arg-type]


class Declarator(View):
    """`name [array] [= initializer]`"""

    __slots__ = ()
    KINDS = ("declarator",)

    @property
    def name_token(self) -> Token:
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return str(self.syntax.children[0])

    @property
    def array(self) -> Tree | None:
        kids = self.syntax.children
        if len(kids) > 1 and isinstance(kids[1], Tree) and kids[1].data == "array_specifier":
            return kids[1]
        return None

    @property
    def initializer(self) -> Node | None:
        return declarator_initializer(self.syntax)


class FullySpecifiedType(View):
    """`[qualifiers] type`"""

    __slots__ = ()
    KINDS = ("fully_specified_type",)

    @property
    def qualifier(self) -> TypeQualifier | None:
        kids = self.syntax.children
        return TypeQualifier(kids[0]) if len(kids) > 1 else None  # type: ignore[arg-type]

    @property
    def type(self) -> TypeSpecifier:
        return TypeSpecifier(self.syntax.children[-1])  # type: ignore[arg-type]

    @property
    def qualifiers(self) -> list[str]:
        """The qualifier words (`const`, `highp`, `uniform` ...); a layout is left out."""
        kids = self.syntax.children
        return TypeQualifier(kids[0]).words if len(kids) > 1 else []  # type: ignore[arg-type]

    @property
    def is_const(self) -> bool:
        return "const" in self.qualifiers


class TypeSpecifier(View):
    """`float`, `vec3[2]`, `S`, or `struct S { ... }` in place."""

    __slots__ = ()
    KINDS = ("type_specifier",)

    @property
    def head(self) -> Node:
        """The type's name token, or its struct_specifier."""
        return self.syntax.children[0]

    @property
    def struct(self) -> StructSpecifier | None:
        head = self.syntax.children[0]
        if isinstance(head, Tree):
            return StructSpecifier(head)
        return None

    @property
    def name(self) -> str:
        """The type's name; a struct specifier's name, or "struct" when it has none."""
        head = self.syntax.children[0]
        if isinstance(head, Token):
            return str(head)
        return StructSpecifier(head).name or "struct"

    @property
    def array(self) -> Tree | None:
        kids = self.syntax.children
        return kids[1] if len(kids) > 1 else None  # type: ignore[return-value]


class ArraySpecifier(View):
    """`[3]`, `[]`, `[2][N]`: the size expressions that are written."""

    __slots__ = ()
    KINDS = ("array_specifier",)

    @property
    def sizes(self) -> list[Node]:
        return list(self.syntax.children)


class StructSpecifier(View):
    """`struct [name] { members }`"""

    __slots__ = ()
    KINDS = ("struct_specifier",)

    @property
    def name(self) -> str | None:
        token = _first_token(self.syntax)
        return str(token) if token is not None else None

    @property
    def members(self) -> list[StructMember]:
        return [
            StructMember(c)
            for c in self.syntax.children
            if isinstance(c, Tree) and c.data == "struct_member"
        ]


class StructMember(View):
    """`[qualifiers] type a, b[2];` in a struct or an interface block."""

    __slots__ = ()
    KINDS = ("struct_member",)

    @property
    def qualifier(self) -> TypeQualifier | None:
        node = _first_tree(self.syntax, "type_qualifier")
        return TypeQualifier(node) if node is not None else None

    @property
    def type(self) -> TypeSpecifier:
        return TypeSpecifier(_first_tree(self.syntax, "type_specifier"))  # type: ignore[arg-type]

    @property
    def declarators(self) -> list[StructDeclarator]:
        return [
            StructDeclarator(c)
            for c in self.syntax.children
            if isinstance(c, Tree) and c.data == "struct_declarator"
        ]


class StructDeclarator(View):
    """`name [array]` of a struct member."""

    __slots__ = ()
    KINDS = ("struct_declarator",)

    @property
    def name_token(self) -> Token:
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return str(self.syntax.children[0])

    @property
    def array(self) -> Tree | None:
        kids = self.syntax.children
        return kids[1] if len(kids) > 1 else None  # type: ignore[return-value]


class TypeQualifier(View):
    """`const highp`, `layout(location = 0) out` ..."""

    __slots__ = ()
    KINDS = ("type_qualifier",)

    @property
    def words(self) -> list[str]:
        """The qualifier keywords, in order; a layout qualifier is not one of them."""
        return [str(t) for t in self.syntax.children if isinstance(t, Token)]

    @property
    def tokens(self) -> list[Token]:
        return [t for t in self.syntax.children if isinstance(t, Token)]

    @property
    def layout(self) -> LayoutQualifier | None:
        node = _first_tree(self.syntax, "layout_qualifier")
        return LayoutQualifier(node) if node is not None else None


class LayoutQualifier(View):
    __slots__ = ()
    KINDS = ("layout_qualifier",)

    @property
    def items(self) -> list[LayoutItem]:
        return [LayoutItem(c) for c in self.syntax.children]  # type: ignore[arg-type]


class LayoutItem(View):
    """`location = 0` or `std140`"""

    __slots__ = ()
    KINDS = ("layout_item",)

    @property
    def name(self) -> str:
        return str(self.syntax.children[0])

    @property
    def value(self) -> Token | None:
        kids = self.syntax.children
        return kids[1] if len(kids) > 1 else None  # type: ignore[return-value]


class PrecisionDeclaration(View):
    """`precision highp float;`"""

    __slots__ = ()
    KINDS = ("precision_declaration",)

    @property
    def precision(self) -> str:
        return str(self.syntax.children[0])

    @property
    def type(self) -> TypeSpecifier:
        return TypeSpecifier(self.syntax.children[1])  # type: ignore[arg-type]


class BlockDeclaration(View):
    """`uniform Block { members } [instance [array]];`"""

    __slots__ = ()
    KINDS = ("block_declaration",)

    @property
    def qualifier(self) -> TypeQualifier:
        return TypeQualifier(self.syntax.children[0])  # type: ignore[arg-type]

    @property
    def block_name(self) -> str:
        return str(self.syntax.children[1])

    @property
    def members(self) -> list[StructMember]:
        return [
            StructMember(c)
            for c in self.syntax.children
            if isinstance(c, Tree) and c.data == "struct_member"
        ]

    @property
    def instance_name(self) -> str | None:
        names = [c for c in self.syntax.children[2:] if isinstance(c, Token)]
        return str(names[0]) if names else None

    @property
    def array(self) -> Tree | None:
        return _first_tree(self.syntax, "array_specifier")


class QualifierDeclaration(View):
    """`invariant gl_Position;` or a lone `layout(...) out;`"""

    __slots__ = ()
    KINDS = ("qualifier_declaration",)

    @property
    def qualifier(self) -> TypeQualifier:
        return TypeQualifier(self.syntax.children[0])  # type: ignore[arg-type]

    @property
    def names(self) -> list[str]:
        return [str(c) for c in self.syntax.children[1:]]


# --- statements ----------------------------------------------------------------------------


class CompoundStatement(View):
    """`{ statements }`"""

    __slots__ = ()
    KINDS = ("compound_statement",)

    @property
    def statements(self) -> list[Node]:
        return list(self.syntax.children)


class DeclarationStatement(View):
    """A declaration as a statement."""

    __slots__ = ()
    KINDS = ("declaration_statement",)

    @property
    def declaration(self) -> Tree:
        """A variable_declaration, function_prototype, precision_declaration ..."""
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def variables(self) -> VariableDeclaration | None:
        return VariableDeclaration.cast(self.syntax.children[0])


class ExpressionStatement(View):
    """`expression;`"""

    __slots__ = ()
    KINDS = ("expression_statement",)

    @property
    def expression(self) -> Node:
        return self.syntax.children[0]


class EmptyStatement(View):
    """`;`"""

    __slots__ = ()
    KINDS = ("empty_statement",)


class IfStatement(View):
    """`if (condition) then_branch [else else_branch]`"""

    __slots__ = ()
    KINDS = ("if_statement",)

    @property
    def condition(self) -> Node:
        return self.syntax.children[0]

    @property
    def then_branch(self) -> Node:
        return self.syntax.children[1]

    @property
    def else_branch(self) -> Node | None:
        kids = self.syntax.children
        return kids[2] if len(kids) > 2 else None


class SwitchStatement(View):
    """`switch (selector) { body }`: the labels are statements of the body."""

    __slots__ = ()
    KINDS = ("switch_statement",)

    @property
    def selector(self) -> Node:
        return self.syntax.children[0]

    @property
    def body(self) -> list[Node]:
        return self.syntax.children[1:]


class CaseLabel(View):
    """`case value:`"""

    __slots__ = ()
    KINDS = ("case_label",)

    @property
    def value(self) -> Node:
        return self.syntax.children[0]


class DefaultLabel(View):
    """`default:`"""

    __slots__ = ()
    KINDS = ("default_label",)


class WhileStatement(View):
    """`while (condition) body`; the condition may declare a variable."""

    __slots__ = ()
    KINDS = ("while_statement",)

    @property
    def condition(self) -> Node:
        """The condition expression, or its condition_declaration."""
        return self.syntax.children[0]

    @property
    def declaration(self) -> ConditionDeclaration | None:
        return ConditionDeclaration.cast(self.syntax.children[0])

    @property
    def body(self) -> Node:
        return self.syntax.children[1]


class ConditionDeclaration(View):
    """`type name = initializer` as a while condition."""

    __slots__ = ()
    KINDS = ("condition_declaration",)

    @property
    def type(self) -> FullySpecifiedType:
        return FullySpecifiedType(self.syntax.children[0])  # type: ignore[arg-type]

    @property
    def name_token(self) -> Token:
        return self.syntax.children[1]  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return str(self.syntax.children[1])

    @property
    def initializer(self) -> Node:
        return self.syntax.children[2]


class DoStatement(View):
    """`do body while (condition);`"""

    __slots__ = ()
    KINDS = ("do_statement",)

    @property
    def body(self) -> Node:
        return self.syntax.children[0]

    @property
    def condition(self) -> Node:
        return self.syntax.children[1]


class ForStatement(View):
    """`for (init condition? ; update?) body`. The init is a statement (a declaration, an
    expression statement or an empty one); the condition and update are expressions, either
    absent. Which of the two a lone one is the parser notes (`for_parts`)."""

    __slots__ = ()
    KINDS = ("for_statement",)

    @property
    def init(self) -> Tree:
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def condition(self) -> Node | None:
        return for_parts(self.syntax)[1]

    @property
    def update(self) -> Node | None:
        return for_parts(self.syntax)[2]

    @property
    def body(self) -> Node:
        return self.syntax.children[-1]


class JumpStatement(View):
    """`continue;`, `break;`, `return [value];`, `discard;`"""

    __slots__ = ()
    KINDS = ("jump_statement",)

    @property
    def keyword(self) -> str:
        return str(self.syntax.children[0])

    @property
    def value(self) -> Node | None:
        """The returned expression."""
        kids = self.syntax.children
        return kids[1] if len(kids) > 1 else None


# --- expressions ---------------------------------------------------------------------------


class Sequence(View):
    """`left, right` (the comma operator)."""

    __slots__ = ()
    KINDS = ("sequence",)

    @property
    def left(self) -> Node:
        return self.syntax.children[0]

    @property
    def right(self) -> Node:
        return self.syntax.children[1]


class Assignment(View):
    """`target op value` with op one of `=`, `+=`, `*=` ..."""

    __slots__ = ()
    KINDS = ("assignment",)

    @property
    def target(self) -> Node:
        return self.syntax.children[0]

    @property
    def op(self) -> str:
        return str(self.syntax.children[1])

    @property
    def op_token(self) -> Token:
        return self.syntax.children[1]  # type: ignore[return-value]

    @property
    def value(self) -> Node:
        return self.syntax.children[2]


class Ternary(View):
    """`condition ? if_true : if_false`"""

    __slots__ = ()
    KINDS = ("ternary",)

    @property
    def condition(self) -> Node:
        return self.syntax.children[0]

    @property
    def if_true(self) -> Node:
        return self.syntax.children[1]

    @property
    def if_false(self) -> Node:
        return self.syntax.children[2]


class Binary(View):
    """`left op right`"""

    __slots__ = ()
    KINDS = ("binary",)

    @property
    def left(self) -> Node:
        return self.syntax.children[0]

    @property
    def op(self) -> str:
        return str(self.syntax.children[1])

    @property
    def op_token(self) -> Token:
        return self.syntax.children[1]  # type: ignore[return-value]

    @property
    def right(self) -> Node:
        return self.syntax.children[2]


class Unary(View):
    """`op operand` with op one of `+ - ! ~`."""

    __slots__ = ()
    KINDS = ("unary",)

    @property
    def op(self) -> str:
        return str(self.syntax.children[0])

    @property
    def operand(self) -> Node:
        return self.syntax.children[1]


class Prefix(View):
    """`++operand`, `--operand`"""

    __slots__ = ()
    KINDS = ("prefix",)

    @property
    def op(self) -> str:
        return str(self.syntax.children[0])

    @property
    def operand(self) -> Node:
        return self.syntax.children[1]


class Postfix(View):
    """`operand++`, `operand--`"""

    __slots__ = ()
    KINDS = ("postfix",)

    @property
    def operand(self) -> Node:
        return self.syntax.children[0]

    @property
    def op(self) -> str:
        return str(self.syntax.children[1])


class Index(View):
    """`base[index]`"""

    __slots__ = ()
    KINDS = ("index",)

    @property
    def base(self) -> Node:
        return self.syntax.children[0]

    @property
    def index(self) -> Node:
        return self.syntax.children[1]


class Call(View):
    """`callee(arguments)`; the callee is a variable, or a field for `a.length()`."""

    __slots__ = ()
    KINDS = ("call",)

    @property
    def callee(self) -> Node:
        return self.syntax.children[0]

    @property
    def callee_name(self) -> str | None:
        """`f` for `f(...)`; None for a method call such as `v.length()`."""
        return callee_name(self.syntax)

    @property
    def arguments(self) -> list[Node]:
        return call_arguments(self.syntax)


class Constructor(View):
    """`type(arguments)`: `vec3(1.0)`, `float[2](a, b)`, `S(1, 2)`."""

    __slots__ = ()
    KINDS = ("constructor",)

    @property
    def type(self) -> TypeSpecifier:
        return TypeSpecifier(self.syntax.children[0])  # type: ignore[arg-type]

    @property
    def type_name(self) -> str:
        """The constructed type's name (`vec3`, `S`), its array part left out."""
        return TypeSpecifier(self.syntax.children[0]).name  # type: ignore[arg-type]

    @property
    def arguments(self) -> list[Node]:
        return call_arguments(self.syntax)


class Field(View):
    """`base.name`: a struct member or a swizzle."""

    __slots__ = ()
    KINDS = ("field",)

    @property
    def base(self) -> Node:
        return self.syntax.children[0]

    @property
    def name_token(self) -> Token:
        return self.syntax.children[1]  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return str(self.syntax.children[1])


class Arguments(View):
    """The argument list of a call or constructor."""

    __slots__ = ()
    KINDS = ("arguments",)

    @property
    def items(self) -> list[Node]:
        return list(self.syntax.children)


class Variable(View):
    """A name read or written."""

    __slots__ = ()
    KINDS = ("variable",)

    @property
    def token(self) -> Token:
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def name(self) -> str:
        return str(self.syntax.children[0])


class IntLiteral(View):
    """`3`, `0x1F`, `7u`"""

    __slots__ = ()
    KINDS = ("int_literal",)

    @property
    def token(self) -> Token:
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def text(self) -> str:
        return str(self.syntax.children[0])

    @property
    def value(self) -> int | None:
        return int_value(str(self.syntax.children[0]))


class FloatLiteral(View):
    """`1.0`, `.5`, `1e3`, `2.0f`"""

    __slots__ = ()
    KINDS = ("float_literal",)

    @property
    def token(self) -> Token:
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def text(self) -> str:
        return str(self.syntax.children[0])

    @property
    def value(self) -> float:
        return float(str(self.syntax.children[0]).rstrip("fF"))


class BoolLiteral(View):
    """`true`, `false`"""

    __slots__ = ()
    KINDS = ("bool_literal",)

    @property
    def token(self) -> Token:
        return self.syntax.children[0]  # type: ignore[return-value]

    @property
    def value(self) -> bool:
        return str(self.syntax.children[0]) == "true"


# --- accessors without a view, for the hot paths -------------------------------------------


def token_text(node: object) -> str | None:
    """The text of the one token of a variable or literal node (`x`, `1.0`), else None."""
    if isinstance(node, Tree) and node.data in _LEAVES:
        return str(node.children[0])
    return None


_LEAVES = frozenset({"variable", "int_literal", "float_literal", "bool_literal"})


def variable_name(node: object) -> str | None:
    """`x` for a variable node, else None."""
    if isinstance(node, Tree) and node.data == "variable":
        return str(node.children[0])
    return None


def callee_name(call: Tree) -> str | None:
    """`f` for a call `f(...)`; None for a method call such as `v.length()`."""
    head = call.children[0]
    return str(head.children[0]) if isinstance(head, Tree) and head.data == "variable" else None


def call_arguments(call: Tree) -> list[Node]:
    """The argument expressions of a call or constructor."""
    kids = call.children
    if len(kids) > 1:
        args = kids[1]
        if isinstance(args, Tree) and args.data == "arguments":
            return list(args.children)
    return []


def binary_parts(node: Tree) -> tuple[Node, str, Node]:
    """(left, operator, right) of a binary or assignment node."""
    left, op, right = node.children
    return left, str(op), right


def operand(node: Tree) -> Node:
    """The operand of a unary, prefix or postfix node."""
    kids = node.children
    return kids[0] if node.data == "postfix" else kids[1]


def operator(node: Tree) -> str:
    """The operator of a unary, prefix, postfix, binary or assignment node."""
    kids = node.children
    return str(kids[0] if node.data in ("unary", "prefix") else kids[1])


def first_child(node: Tree) -> Node:
    """The base of a field or index, the condition of an if or ternary, the expression of an
    expression statement: a node's first part, where the caller knows which that is."""
    return node.children[0]


def leaf_text(node: Tree) -> str:
    """The text of the one token of a variable or literal node, where the caller knows it is
    one (`token_text` checks)."""
    return str(node.children[0])


def field_parts(node: Tree) -> tuple[Node, str]:
    """(base, name) of a field node: `v.xy` -> (v, "xy")."""
    base, name = node.children
    return base, str(name)


def index_parts(node: Tree) -> tuple[Node, Node]:
    """(base, index) of an index node: `a[i]` -> (a, i)."""
    base, index = node.children
    return base, index


def ternary_parts(node: Tree) -> tuple[Node, Node, Node]:
    """(condition, if_true, if_false) of a ternary node."""
    condition, if_true, if_false = node.children
    return condition, if_true, if_false


def if_parts(node: Tree) -> tuple[Node, Node, Node | None]:
    """(condition, then_branch, else_branch or None) of an if statement."""
    kids = node.children
    return kids[0], kids[1], kids[2] if len(kids) > 2 else None


def jump_parts(node: Tree) -> tuple[str, Node | None]:
    """(keyword, returned expression or None) of a jump statement."""
    kids = node.children
    return str(kids[0]), kids[1] if len(kids) > 1 else None


def declarators(node: Tree) -> list[Tree]:
    """The declarator nodes of a variable declaration (none for a bare struct)."""
    return node.children[1:]  # type: ignore[return-value]


def definition_parts(node: Tree) -> tuple[Tree, Tree]:
    """(prototype, body) of a function definition."""
    prototype, body = node.children
    return prototype, body  # type: ignore[return-value]


def declarator_initializer(node: Tree) -> Node | None:
    """The initializer of a declarator, None when it has none."""
    kids = node.children
    if len(kids) < 2:
        return None
    last = kids[-1]
    if len(kids) == 2 and isinstance(last, Tree) and last.data == "array_specifier":
        return None
    return last


def for_parts(node: Tree) -> tuple[Tree, Node | None, Node | None, Node]:
    """(init, condition, update, body) of a for statement, the two middle ones None when
    absent. The parser notes which are there (`meta.for_parts`); a tree built by hand
    without that note is read with a lone middle part as the condition."""
    kids = node.children
    init, body = kids[0], kids[-1]
    if len(kids) == 4:
        return init, kids[1], kids[2], body  # type: ignore[return-value]
    if len(kids) == 2:
        return init, None, None, body  # type: ignore[return-value]
    parts = getattr(node.meta, "for_parts", (True, False))
    if parts[0]:
        return init, kids[1], None, body  # type: ignore[return-value]
    return init, None, kids[1], body  # type: ignore[return-value]


def loop_condition(node: Tree) -> Node | None:
    """The condition of a for, while or do statement: None for a for without one; a while's
    may be a condition_declaration."""
    if node.data == "for_statement":
        return for_parts(node)[1]
    kids = node.children
    return kids[0] if node.data == "while_statement" else kids[1]


def loop_parts(node: Tree) -> list[Node]:
    """The parts of a for, while or do statement that run on every pass, in source order: the
    condition, the update and the body that are there (a for's init runs once)."""
    if node.data == "for_statement":
        _, condition, update, body = for_parts(node)
        return [p for p in (condition, update, body) if p is not None]
    return list(node.children)


def int_value(text: str) -> int | None:
    """The value of an int literal's text (decimal, octal, hex, `u` suffix)."""
    text = text.rstrip("uU")
    try:
        if text.lower().startswith("0x"):
            return int(text, 16)
        if len(text) > 1 and text.startswith("0"):
            return int(text, 8)
        return int(text)
    except ValueError:
        return None


def cast_any(node: object, *views: type[_V]) -> _V | None:
    """The first of these views that `node` is."""
    for cls in views:
        found = cls.cast(node)
        if found is not None:
            return found
    return None


# --- more accessors without a view (the data-flow analysis) ---------------------------------


def assigned_target(node: Tree) -> Node:
    """The lvalue an assignment, prefix or postfix node writes (`x` of `x += 1.`, `++x`)."""
    kids = node.children
    return kids[1] if node.data == "prefix" else kids[0]


def field_name(node: Tree) -> str:
    """`xyz` of a field node `v.xyz` (field_parts' second half)."""
    return field_parts(node)[1]


def index_expression(node: Tree) -> Node:
    """`i + 1` of an index node `a[i + 1]` (index_parts' second half)."""
    return index_parts(node)[1]
