"""``rig lab``: the virtual lab - stands A and B operated from a web page served on this machine (docs/lab.md).

Serves the page and its JSON API on --host (default 127.0.0.1) and --port (0: any free port),
opens the page in the default browser unless --no-browser, and runs until Ctrl-C. The line
``rig lab: serving http://HOST:PORT/`` tells where (tests read it).
"""

from __future__ import annotations

import logging
import threading
import webbrowser
from pathlib import Path

from rig.errors import MissingExtraError, ParameterError

DEFAULT_PORT = 8765


def add_parser(subparsers) -> None:
    """Register ``rig lab``."""
    parser = subparsers.add_parser("lab", help="the virtual lab: operate the stands from a web page",
                                   description="Serve the virtual lab (stands A and B from a web page) until Ctrl-C.")
    parser.add_argument("--host", default="127.0.0.1", help="address to listen on (default: 127.0.0.1)")
    parser.add_argument("--port", type=int, default=DEFAULT_PORT,
                        help=f"port (default: {DEFAULT_PORT}; 0: any free port)")
    parser.add_argument("--no-browser", action="store_true", help="do not open the page in the default browser")
    parser.add_argument("--class", "--exercises", dest="classfile", type=Path, default=None, metavar="FILE",
                        help="a teacher's class file (TOML, docs/lab.md): students or a join code, exercises, "
                             "deadlines, attempts, tolerances; prints the teacher's link")
    parser.add_argument("-o", "--output", type=Path, default=Path("lab-sessions"), metavar="DIR",
                        help="folder of saved sessions (DIR/<session>/log.h5; default: ./lab-sessions)")
    parser.add_argument("--state", type=Path, default=None, metavar="DIR",
                        help="folder the sessions are kept in, so a restarted server gives them back "
                             "(default: DIR of -o, subfolder state)")
    parser.set_defaults(handler=main)


LAB_PACKAGES = ("flask", "werkzeug")
"""The web server's libraries, installed by the extra ``lab`` (``pip install "friction-rig[lab]"``)."""


def main(args) -> int:
    try:  # the server's libraries load only for ``rig lab``; they come with the extra "lab"
        from werkzeug.serving import make_server

        from rig.lab.app import Lab, create_app
    except ModuleNotFoundError as error:
        if (error.name or "").partition(".")[0] not in LAB_PACKAGES:
            raise
        raise MissingExtraError("rig lab", "Flask", "lab") from None
    from rig import validate
    from rig.lab.exercises import ClassFile

    logging.getLogger("werkzeug").setLevel(logging.WARNING)  # no line per request on the console
    port = validate.integer("--port", args.port, 0, 65535)
    classfile = None if args.classfile is None else ClassFile.load(args.classfile)
    lab = Lab(args.output, classfile, args.state)
    app = create_app(lab)
    try:
        server = make_server(args.host, port, app, threaded=True)
    except (OSError, SystemExit) as error:  # werkzeug reports a taken port by printing and exiting
        raise ParameterError("--port", port, f"a free port on {args.host} ({error})") from None
    url = f"http://{args.host}:{server.server_port}/"
    print(f"rig lab: serving {url} (Ctrl-C stops)", flush=True)
    if lab.roster is not None:
        print(f"rig lab: teacher's link {url}#teacher={lab.roster.teacher_token} (keep it secret; also in "
              f"{lab.store.folder / 'teacher-token'}); students' tokens: {lab.store.folder / 'tokens.csv'}"
              + ("" if classfile.join_code is None else f"; join code: {classfile.join_code}"), flush=True)
        threading.Thread(target=lab.prepare, args=(lambda line: print(f"rig lab: {line}", flush=True),),
                         daemon=True).start()
    if not args.no_browser:
        threading.Timer(0.5, webbrowser.open, (url,)).start()
    server.serve_forever()  # returns on Ctrl-C (werkzeug catches KeyboardInterrupt and closes the socket)
    print("rig lab: stopped", flush=True)
    return 0
