#!/usr/bin/env python3
"""Saves an edit the way an editor does, for tests/chapters/live_reload.sh (scenarios save-STYLE).

    live_reload_save.py FILE LINE STYLE

LINE goes before the file's last '}'. Between the steps of a save there is a pause longer than
the chapter's poll interval, so that the chapter may look at the file in between:
  in-place    one write of the whole file;
  truncate    the file emptied, then written (two steps);
  rename-new  a new file written next to it, then renamed over it;
  rename-old  the file moved aside, a new one written, the old one removed (vim's default);
  delete      the file removed, then created again.
"""
import os
import sys
import time

PAUSE = 0.4  # seconds: several times the 50 ms between polls


def write(path, content):
    with open(path, 'w') as f:
        f.write(content)


def main():
    path, line, style = sys.argv[1], sys.argv[2], sys.argv[3]
    text = open(path).read()
    end = text.rindex('}')
    start = text.rindex('\n', 0, end) + 1
    edited = text[:start] + line + '\n' + text[start:]
    if style == 'in-place':
        write(path, edited)
    elif style == 'truncate':
        open(path, 'w').close()
        time.sleep(PAUSE)
        write(path, edited)
    elif style == 'rename-new':
        write(path + '.tmp', edited)
        os.replace(path + '.tmp', path)
    elif style == 'rename-old':
        os.replace(path, path + '~')
        time.sleep(PAUSE)
        write(path, edited)
        os.remove(path + '~')
    elif style == 'delete':
        os.remove(path)
        time.sleep(PAUSE)
        write(path, edited)
    else:
        sys.exit('live_reload_save: unknown save style ' + style)


if __name__ == '__main__':
    main()
