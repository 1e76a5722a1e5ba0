"""What AeroNC's HTML reports share: the style sheet, escaping, numbers, pass/FAIL marks and
tables, so that every report reads the same way."""
import html

STYLE = """
body { font-family: 'DejaVu Sans', Arial, sans-serif; margin: 24px 32px; color: #222; max-width: 1280px; }
h1 { font-size: 22px; margin-bottom: 2px; } h2 { font-size: 18px; border-bottom: 2px solid #3a6ea5;
padding-bottom: 2px; margin-top: 28px; } h3 { font-size: 15px; margin: 18px 0 6px; }
table { border-collapse: collapse; margin: 6px 0 12px; font-size: 13px; }
th, td { border: 1px solid #c8c8c8; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #eef2f7; } td.n { text-align: right; font-variant-numeric: tabular-nums; }
tr.process td { background: #f6f6f6; font-weight: bold; } .ok { color: #11772b; font-weight: bold; }
.fail { color: #b3141b; font-weight: bold; } .muted { color: #777; } .small { font-size: 12px; }
img { max-width: 100%; border: 1px solid #ddd; margin: 6px 0; }
.summary td:first-child { font-weight: bold; background: #fafafa; }
.banner { font-size: 17px; font-weight: bold; padding: 10px 14px; margin: 0 0 14px; border: 3px solid; }
.banner.ready { color: #11772b; border-color: #11772b; background: #eef8f0; }
.banner.notready { color: #b3141b; border-color: #b3141b; background: #fdeeee; }
"""


def esc(x):
    """x as HTML text."""
    return html.escape(str(x))


def num(x, digits=1):
    """A number with thousands separators and `digits` decimals; a dash for None."""
    if x is None:
        return "&ndash;"
    try:
        return "{:,.{}f}".format(float(x), digits)
    except (TypeError, ValueError):
        return esc(x)


def verdict(ok):
    return '<span class="ok">pass</span>' if ok else '<span class="fail">FAIL</span>'


def table(head, rows, numeric=()):
    """A table: head cells escaped; row cells as given (HTML), right-aligned in the numeric columns."""
    out = ["<table><tr>{}</tr>".format("".join("<th>{}</th>".format(esc(h)) for h in head))]
    for r in rows:
        out.append("<tr>{}</tr>".format("".join(
            "<td class='n'>{}</td>".format(c) if i in numeric else "<td>{}</td>".format(c) for i, c in enumerate(r))))
    out.append("</table>")
    return "".join(out)
