"""Lines, comments, quoted tokens, columns and numbers of the keyword formats."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.lexer import TextFileError, decode, format_number, integer, number, quote_token, split_lines


def lines_of(text, **options):
    diagnostics = Diagnostics()
    return split_lines(text, "f.txt", diagnostics, **options), diagnostics


def test_comments_blank_lines_and_tabs_are_skipped():
    lines, diagnostics = lines_of("# comment\n  ; also a comment\n\n\t \t\nworld  a.wld\t\n")
    assert [(line.number, [t.text for t in line.tokens]) for line in lines] == [(5, ["world", "a.wld"])]
    assert not diagnostics.items


def test_columns_are_one_based_and_count_tabs_as_one():
    (line,), _ = lines_of("\tpsd  PSD_FRONT\t1")
    assert [(t.text, t.column) for t in line.tokens] == [("psd", 2), ("PSD_FRONT", 7), ("1", 17)]


def test_quotes_group_spaces_and_are_stripped():
    (line,), _ = lines_of("""world "C:\\My Files\\a b.wld" 'x y' z""")
    assert [t.text for t in line.tokens] == ["world", "C:\\My Files\\a b.wld", "x y", "z"]
    assert line.tokens[1].quoted and not line.tokens[3].quoted


def test_unterminated_quote_is_reported_with_its_column():
    (line,), diagnostics = lines_of('world "abc def')
    assert line.tokens[1].text == "abc def"
    (d,) = diagnostics.items
    assert (d.kind, d.location.line, d.location.column) == ("error", 1, 7)
    assert "closing" in d.message


def test_unterminated_quote_is_a_warning_when_not_strict():
    _, diagnostics = lines_of("floor_texture 'abc", strict=False)
    assert [d.kind for d in diagnostics.items] == ["warning"]


def test_inline_comments_only_where_asked():
    (line,), _ = lines_of("push 3845 0 180   ; +900", comment_chars=";")
    assert [t.text for t in line.tokens] == ["push", "3845", "0", "180"]
    (line,), _ = lines_of("name a;b")
    assert line.tokens[1].text == "a;b"


def test_decode_handles_crlf_cr_bom_and_latin1():
    assert decode(b"\xef\xbb\xbfa\r\nb\rc") == "a\nb\nc"
    assert decode("caf\xe9".encode("latin-1")) == "caf\xe9"


def test_decode_rejects_binary():
    with pytest.raises(TextFileError):
        decode(b"abc\x00def")


@pytest.mark.parametrize(
    "text, value",
    [
        ("90", 90.0),
        ("-90", -90.0),
        ("+900", 900.0),
        ("22.7", 22.7),
        (".5", 0.5),
        ("1.", 1.0),
        ("1e3", 1000.0),
        ("-0", 0.0),
    ],
)
def test_numbers(text, value):
    assert number(text) == value


@pytest.mark.parametrize("text", ["nan", "inf", "-infinity", "1_000", "0x10", "", "1e999", "1e10", "1,5", "abc", "--1"])
def test_not_numbers(text):
    assert number(text) is None


def test_negative_zero_is_plain_zero():
    assert math.copysign(1, number("-0.0")) == 1


def test_integers():
    assert integer("-200") == -200 and integer("1.0") is None


@settings(max_examples=300)
@given(st.floats(min_value=-1e9, max_value=1e9))
def test_format_number_reads_back_exactly(value):
    assert number(format_number(value)) == value


@given(st.text(max_size=40))
def test_quote_token_reads_back(text):
    if '"' in text and "'" in text or "\n" in text or "\r" in text:
        return  # not representable on one line
    (line,), diagnostics = lines_of("k " + quote_token(text))
    assert not diagnostics.items
    assert [t.text for t in line.tokens[1:]] == [text]
