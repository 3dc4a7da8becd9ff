#!/usr/bin/env python3
"""Maintainer's tool for the Qt Linguist catalogues in translations/ (docs/glossary.md).

  ts_tool.py pending TS [CONTEXT...]   unfinished messages as a JSON skeleton
                                       {context: {source: ""}} (a list for plurals)
  ts_tool.py apply TS JSON...          fills translations from JSON files of that shape
                                       (a message not in TS is reported, not added)
  ts_tool.py english TS                makes an English catalogue finished: each
                                       translation is its source (plurals: singular
                                       with %n → 1 form, the source as the other)
  ts_tool.py stats TS                  finished / unfinished / obsolete per context
  ts_tool.py carry TS OLD_TS CONTEXT...
                                       after code moved between classes: fills each
                                       unfinished message of TS with the translation its
                                       source had in OLD_TS (a copy taken before
                                       lupdate) in the first of the CONTEXTs that has it

The test suite's check (tests/i18n) does not use this script: it runs lupdate and
reads the catalogues itself.
"""
import json
import sys
import xml.etree.ElementTree as ET


def load(path):
    return ET.parse(path)


def messages(tree):
    for ctx in tree.getroot().findall('context'):
        name = ctx.find('name').text or ''
        for m in ctx.findall('message'):
            yield name, m


def is_numerus(m):
    return m.get('numerus') == 'yes'


def source(m):
    return m.find('source').text or ''


def set_translation(m, value):
    tr = m.find('translation')
    if tr is None:
        tr = ET.SubElement(m, 'translation')
    for child in list(tr):
        tr.remove(child)
    if is_numerus(m):
        forms = value if isinstance(value, list) else [value, value]
        tr.text = None
        for f in forms:
            nf = ET.SubElement(tr, 'numerusform')
            nf.text = f
    else:
        if isinstance(value, list):
            value = value[-1]
        tr.text = value
    if 'type' in tr.attrib:
        del tr.attrib['type']


def save(tree, path):
    tree.write(path, encoding='utf-8', xml_declaration=True)
    # lupdate's doctype, so lupdate and lrelease read it as before
    with open(path, encoding='utf-8') as f:
        text = f.read()
    if '<!DOCTYPE TS>' not in text:
        text = text.replace("?>", "?>\n<!DOCTYPE TS>", 1)
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text + ('' if text.endswith('\n') else '\n'))


def pending(path, contexts):
    out = {}
    for ctx, m in messages(load(path)):
        if contexts and ctx not in contexts:
            continue
        tr = m.find('translation')
        if tr is not None and tr.get('type') in ('unfinished',) or tr is None:
            out.setdefault(ctx, {})[source(m)] = ["", ""] if is_numerus(m) else ""
    json.dump(out, sys.stdout, ensure_ascii=False, indent=1)
    print()


def apply(path, files):
    tree = load(path)
    table = {}
    for f in files:
        with open(f, encoding='utf-8') as fh:
            for ctx, entries in json.load(fh).items():
                for src, tr in entries.items():
                    table[(ctx, src)] = tr
    used = set()
    filled = 0
    for ctx, m in messages(tree):
        key = (ctx, source(m))
        if key in table and table[key] not in ("", ["", ""]):
            set_translation(m, table[key])
            used.add(key)
            filled += 1
    for key in table:
        if key not in used and table[key] not in ("", ["", ""]):
            print(f'not in {path}: [{key[0]}] {key[1][:70]!r}', file=sys.stderr)
    save(tree, path)
    print(f'{path}: {filled} translations filled', file=sys.stderr)


def english(path):
    tree = load(path)
    for ctx, m in messages(tree):
        src = source(m)
        if is_numerus(m):
            tr = m.find('translation')
            forms = [f.text or '' for f in tr.findall('numerusform')] if tr is not None else []
            if tr is not None and tr.get('type') != 'unfinished' and all(forms):
                continue
            print(f'plural needs English forms: [{ctx}] {src!r}', file=sys.stderr)
            continue
        set_translation(m, src)
    save(tree, path)


def stats(path):
    counts = {}
    for ctx, m in messages(load(path)):
        tr = m.find('translation')
        kind = 'finished'
        if tr is None or tr.get('type') == 'unfinished':
            kind = 'unfinished'
        elif tr.get('type') in ('obsolete', 'vanished'):
            kind = 'obsolete'
        c = counts.setdefault(ctx, {'finished': 0, 'unfinished': 0, 'obsolete': 0})
        c[kind] += 1
    for ctx, c in sorted(counts.items()):
        print(f"{c['finished']:5d} {c['unfinished']:5d} {c['obsolete']:5d}  {ctx}")


def carry(path, old_path, contexts):
    old = {}
    for ctx, m in messages(load(old_path)):
        tr = m.find('translation')
        if ctx not in contexts or tr is None or tr.get('type') is not None:
            continue
        forms = [f.text or '' for f in tr.findall('numerusform')]
        old.setdefault(source(m), {})[ctx] = forms if is_numerus(m) else (tr.text or '')
    tree = load(path)
    filled = 0
    for ctx, m in messages(tree):
        tr = m.find('translation')
        if tr is not None and tr.get('type') != 'unfinished':
            continue
        found = old.get(source(m), {})
        for c in contexts:
            if c in found and found[c] not in ('', []):
                set_translation(m, found[c])
                filled += 1
                break
    save(tree, path)
    print(f'{path}: {filled} translations carried from {old_path}', file=sys.stderr)


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    cmd, path = argv[1], argv[2]
    if cmd == 'pending':
        pending(path, set(argv[3:]))
    elif cmd == 'apply':
        apply(path, argv[3:])
    elif cmd == 'english':
        english(path)
    elif cmd == 'stats':
        stats(path)
    elif cmd == 'carry' and len(argv) > 4:
        carry(path, argv[3], argv[4:])
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
