#!/usr/bin/env python3
"""tackle's step service: the page of one problem (`tackle page`) and the checks of the steps a
student types in it, as a WSGI application served by gunicorn with several worker processes.

Usage: python3 -m tackle_step_service FILE [--workers N] [--port N] [--rubric RUBRIC.yaml]
           [--origin URL] [--phase NAME] [--time-limit SECONDS] [--quiet]
       (from a source tree: scripts/step-server FILE ..., with --build DIR)

  GET  /          the page (Problem.page(): the problem, its sketch, the solution form)
  POST /step      {"kind": "equation", "equation": "2*T - F = m_A*ddot(x_A)"}
                  {"kind": "answer", "unknown": "T", "answer": "20 N"}
                  {"kind": "fbd", "fbd": {"body": "B", "forces": [{"name": "T", "at": "pB", "direction": [-1]}]}}
                  -> the verdict as Problem.check_equation / check / check_fbd give it; a free
                     body diagram with names the problem does not have: {"verdict": "invalid",
                     "summary": "..."}
  POST /solution  {"steps": [{"equation": ...}, {"answer": ..., "unknown": ...}, {"fbd": {...}}],
                   "rubric": {...} (optional: the server's --rubric, else 1 point a part)}
                  -> the grade as `tackle check --steps --format json` writes it

A request body is JSON of at most 64 KB with a Content-Length; anything else is a 4xx with
{"error": "..."} (docs/checking.md lists each), from this application or, for what gunicorn
refuses before it (a request line or header it cannot read, two Content-Lengths), from its
workers here. A POST from a page of another origin (its Origin header, or Sec-Fetch-Site) is
refused: only the page this service serves, or one at an --origin given, may post.

The service keeps nothing between requests: each worker process loads the problem when it starts
and answers each request from it alone, so any worker (on this machine or another, behind any
load balancer) gives any request the same answer. A solution's checking stops at its time limit
(--time-limit, 5 s): the steps not begun by then are `undecided` (code `time_limit`); a worker
still at work 25 s past the limit is killed and replaced by gunicorn (that request's connection
is closed unanswered).

The launcher binds 127.0.0.1 (port 0: a free one) itself, prints the page's address as its first
line, and hands the socket to gunicorn (`fd://`), so the address printed is the one served. Behind
a load balancer, run the application under gunicorn with its settings in the environment
(docs/checking.md, "Deploying the step service"):

  TACKLE_STEP_PROBLEM=problem.yaml TACKLE_STEP_HOSTS=steps.example.edu \\
  TACKLE_STEP_ORIGINS=https://steps.example.edu gunicorn --workers 4 --bind 0.0.0.0:8000 tackle_step_service:app
"""
import argparse
import json
import os
import re
import shutil
import socket
import sys
from datetime import datetime

LIMIT = 64 * 1024
DRAIN = 1024 * 1024  # a body too long is read and dropped up to this (then answered 413)
READ_TIMEOUT = 10  # seconds a client has to send its request (else 408 and dropped)
DEFAULT_TIME_LIMIT = 5.0
HARD_TIMEOUT_MARGIN = 25  # gunicorn kills a worker silent for the time limit and this
LOCAL_HOSTS = ("127.0.0.1", "localhost")
METHODS = "GET / or POST /step and /solution"


class Config:
    """What a worker needs to serve one problem (nothing of any request)."""

    def __init__(self, problem, phase="", rubric_file=None, origins=(), hosts=LOCAL_HOSTS, port=None,
                 time_limit=DEFAULT_TIME_LIMIT):
        self.problem = problem
        self.phase = phase
        self.rubric_file = rubric_file
        self.origins = list(origins)
        self.hosts = list(hosts)
        self.port = port  # the port the page is served at (its own origin); None: the request's SERVER_PORT
        self.time_limit = time_limit

    @classmethod
    def from_environ(cls, env=os.environ):
        """TACKLE_STEP_PROBLEM (the description), _PHASE, _RUBRIC (a file), _ORIGINS and _HOSTS
        (separated by spaces or commas; hosts: 127.0.0.1 and localhost unless given), _PORT (the
        port the page's own origin has, when not the one the service listens at), _TIME_LIMIT."""
        problem = env.get("TACKLE_STEP_PROBLEM")
        if not problem:
            raise ValueError("TACKLE_STEP_PROBLEM is not set (the problem's description, a YAML file)")

        def words(name):
            return [w for w in re.split(r"[\s,]+", env.get(name, "")) if w]

        for origin in words("TACKLE_STEP_ORIGINS"):
            check_origin(origin)
        port = env.get("TACKLE_STEP_PORT")
        limit = env.get("TACKLE_STEP_TIME_LIMIT")
        return cls(problem, phase=env.get("TACKLE_STEP_PHASE", ""), rubric_file=env.get("TACKLE_STEP_RUBRIC") or None,
                   origins=words("TACKLE_STEP_ORIGINS"), hosts=words("TACKLE_STEP_HOSTS") or LOCAL_HOSTS,
                   port=int(port) if port else None, time_limit=float(limit) if limit else DEFAULT_TIME_LIMIT)


def check_origin(origin):
    if not re.fullmatch(r"https?://[A-Za-z0-9.\-\[\]:]+", origin):
        raise ValueError("--origin %r is not an origin (expected scheme://host[:port], e.g. https://course.example.edu)" % origin)


def messages(error, name):
    """An InputError's messages without the place in the JSON the page sent (`fbd:1:12: `),
    which means nothing to the student."""
    return re.sub(r"(?m)^%s:\d+:\d+: " % name, "", str(error))


class BadRequest(Exception):
    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


def text_field(data, name):
    value = data.get(name)
    if not isinstance(value, str):
        raise BadRequest(400, "'%s' must be a string" % name)
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise BadRequest(400, "'%s' is not text (it has a lone surrogate)" % name) from None
    return value


def strict_constant(name):
    raise ValueError("%s is not JSON" % name)


def parse_body(body):
    """The request's JSON object; BadRequest for anything else."""
    try:
        data = json.loads(body.decode("utf-8"), parse_constant=strict_constant)
    except (UnicodeDecodeError, ValueError):
        raise BadRequest(400, "the request is not JSON (UTF-8)") from None
    except RecursionError:
        raise BadRequest(400, "the request's JSON is nested too deeply") from None
    if not isinstance(data, dict):
        raise BadRequest(400, "the request is not a JSON object")
    return data


def check_steps(steps):
    """A solution's steps as the page sends them: objects whose texts are strings and whose
    diagram is an object; BadRequest naming the first that is not."""
    if not isinstance(steps, list):
        raise BadRequest(400, "'steps' must be a list")
    for k, step in enumerate(steps, 1):
        if not isinstance(step, dict):
            raise BadRequest(400, "step %d must be an object ({\"equation\": ...}, {\"answer\": ..., \"unknown\": ...} or {\"fbd\": {...}})" % k)
        for name in ("equation", "answer", "unknown"):
            if name in step:
                try:
                    text_field(step, name)
                except BadRequest as e:
                    raise BadRequest(400, "step %d: %s" % (k, e)) from None
        if "fbd" in step and not isinstance(step["fbd"], dict):
            raise BadRequest(400, "step %d: 'fbd' must be an object (body, forces)" % k)


HEADERS = [("Cache-Control", "no-store"), ("X-Content-Type-Options", "nosniff")]
REASONS = {200: "OK", 400: "Bad Request", 403: "Forbidden", 404: "Not Found", 405: "Method Not Allowed",
           408: "Request Timeout", 411: "Length Required", 413: "Payload Too Large", 500: "Internal Server Error"}


class Service:
    """The WSGI application: one problem, loaded when the worker starts; each request answered
    from it alone."""

    def __init__(self, config, tackle=None):
        if tackle is None:
            import tackle  # noqa: E402 (found where the launcher put it, or installed)
        self.tackle = tackle
        self.config = config
        self.problem = tackle.Problem(config.problem, phase=config.phase)
        self.rubric = ""
        if config.rubric_file:
            with open(config.rubric_file, encoding="utf-8") as f:
                self.rubric = f.read()
            try:
                self.problem.check_solution("steps: []", rubric=self.rubric)  # a bad rubric is said now, not at each request
            except ValueError as e:  # (the module names a rubric given as text "rubric": here it is the file)
                raise ValueError(re.sub(r"(?m)^rubric:", config.rubric_file + ":", str(e))) from None
        self.page = self.problem.page().encode("utf-8")
        self.asked = [a["name"] for a in self.problem.answers()]
        self.problem.check_equation("0 = 0")  # the checker made now (about 10 ms), not in a student's first request

    # What a request is answered.
    def __call__(self, environ, start_response):
        status, body, content_type = self.respond(environ)
        headers = [("Content-Type", content_type), ("Content-Length", str(len(body)))] + HEADERS
        if status != 200:
            headers.append(("Connection", "close"))
        start_response("%d %s" % (status, REASONS.get(status, "Error")), headers)
        return [b"" if environ.get("REQUEST_METHOD") == "HEAD" else body]

    def respond(self, environ):
        try:
            return self.route(environ)
        except BadRequest as e:
            return error(e.status, str(e))
        except ValueError as e:  # a parameter the module refuses (its ValueError)
            return error(400, str(e))
        except Exception as e:  # noqa: BLE001 (tackle's own failure: said, never a dropped connection)
            return error(500, "internal error: %s" % e)

    def route(self, environ):
        method = environ.get("REQUEST_METHOD", "GET")
        path = environ.get("PATH_INFO", "") or "/"
        if method == "HEAD":
            return 405, b"", "application/json; charset=utf-8"
        if method not in ("GET", "POST"):
            return error(405, METHODS)
        if not self.host_ok(environ):
            return error(403, "the server answers requests to %s only" % " or ".join(self.config.hosts))
        if method == "GET":
            if path not in ("/", "/index.html"):
                return error(404, "no such page (the page is at /)")
            return 200, self.page, "text/html; charset=utf-8"
        if not self.origin_ok(environ):
            return error(403, "a page of another origin may not post here")
        if path not in ("/step", "/solution"):
            return error(404, "no such endpoint (POST /step or /solution)")
        data = parse_body(read_body(environ))
        result = self.judge_step(data) if path == "/step" else self.judge_solution(data)
        return 200, json.dumps(result).encode("utf-8"), "application/json; charset=utf-8"

    def host_ok(self, environ):
        # Only the names given (this machine's, by default): a page elsewhere cannot reach the
        # service through a name that resolves here (DNS rebinding).
        host = (environ.get("HTTP_HOST") or "").rsplit(":", 1)[0]
        return host in self.config.hosts

    def origin_ok(self, environ):
        # A page of another origin may not post here (a browser says where a request comes
        # from): only this service's own page, or one at an --origin given.
        port = self.config.port or int(environ.get("SERVER_PORT") or 0)
        here = ["http://%s:%d" % (host, port) for host in self.config.hosts]
        origin = environ.get("HTTP_ORIGIN")
        if origin is not None:
            return origin in here + self.config.origins
        return environ.get("HTTP_SEC_FETCH_SITE", "same-origin") in ("same-origin", "none")

    def judge_step(self, data):
        """One step's verdict (a dict), as the module gives it."""
        kind = data.get("kind")
        if kind == "equation":
            return self.problem.check_equation(text_field(data, "equation"))
        if kind == "answer":
            unknown = text_field(data, "unknown")
            if unknown not in self.asked:
                return {"verdict": "invalid", "score": 0.0, "summary": "'%s' is not asked for (asked: %s)" % (unknown, ", ".join(self.asked))}
            return self.problem.check(unknown, text_field(data, "answer"))
        if kind == "fbd":
            fbd = data.get("fbd")
            if not isinstance(fbd, dict):
                raise BadRequest(400, "'fbd' must be an object (body, forces)")
            try:
                return self.problem.check_fbd(fbd)
            except self.tackle.InputError as e:
                return {"verdict": "invalid", "score": 0.0, "summary": messages(e, "fbd")}
        raise BadRequest(400, "'kind' must be equation, answer or fbd")

    def judge_solution(self, data):
        steps = data.get("steps")
        check_steps(steps)
        rubric = self.rubric
        if "rubric" in data:
            if not isinstance(data["rubric"], dict):
                raise BadRequest(400, "'rubric' must be an object ({\"balances\": 4, ...})")
            rubric = json.dumps(data["rubric"])
        try:
            grade, _ = self.problem.check_solution(json.dumps({"steps": steps}), rubric=rubric, time_limit=self.config.time_limit)
            return grade
        except self.tackle.InputError as e:
            return {"verdict": "invalid", "score": 0.0, "summary": messages(e, "solution")}


def error(status, message):
    return status, json.dumps({"error": message}).encode("utf-8"), "application/json; charset=utf-8"


def read_body(environ):
    """The request's body, as its one Content-Length says; BadRequest otherwise."""
    if environ.get("HTTP_TRANSFER_ENCODING"):
        raise BadRequest(411, "send the body with a Content-Length")
    length = environ.get("CONTENT_LENGTH")
    if length is None or length == "":
        raise BadRequest(411, "send the body with a Content-Length")
    if not re.fullmatch(r"[0-9]{1,12}", length):
        raise BadRequest(400, "the Content-Length is not one whole number")
    sock = environ.get("gunicorn.socket")
    if sock is not None:
        sock.settimeout(READ_TIMEOUT)  # a client that stops sending mid-request is answered 408
    if int(length) > LIMIT:
        # Read (up to DRAIN bytes) and dropped: a connection closed with a body unread is reset,
        # and a client still sending would see the reset rather than the 413.
        left = min(int(length), DRAIN)
        try:
            while left > 0:
                chunk = environ["wsgi.input"].read(min(left, 65536))
                if not chunk:
                    break
                left -= len(chunk)
        except OSError:
            pass
        raise BadRequest(413, "the request is longer than %d bytes" % LIMIT)
    try:
        body = environ["wsgi.input"].read(int(length))
    except OSError:  # (socket.timeout, or the client gone)
        body = b""
    if len(body) < int(length):
        raise BadRequest(408, "the request's body is shorter than its Content-Length")
    return body


# The application for a WSGI server (gunicorn tackle_step_service:app), its settings from the
# environment (Config.from_environ), made when a worker first asks for it (as it starts); and
# gunicorn's worker with JSON refusals (--worker-class tackle_step_service.JsonErrorWorker).
_made = {}


def __getattr__(name):
    if name not in ("app", "JsonErrorWorker"):
        raise AttributeError(name)
    if name not in _made:
        _made[name] = Service(Config.from_environ()) if name == "app" else json_worker_class()
    return _made[name]


# gunicorn: a sync worker whose refusals are JSON too, and that gives a client READ_TIMEOUT to
# send its request.
def json_worker_class():
    from gunicorn import util
    from gunicorn.http import errors
    from gunicorn.workers.sync import SyncWorker

    class JsonErrorWorker(SyncWorker):
        def accept(self, listener):
            client, addr = listener.accept()
            client.settimeout(READ_TIMEOUT)
            util.close_on_exec(client)
            self.handle(listener, client, addr)

        def handle_error(self, req, client, addr, exc):
            # What gunicorn refuses before the application sees it, said as the application
            # says its own refusals.
            if isinstance(exc, errors.InvalidHeader) and "CONTENT-LENGTH" in str(exc):
                status, message = 400, "the Content-Length is not one whole number"
            elif isinstance(exc, errors.InvalidHeader) and "TRANSFER-ENCODING" in str(exc) or \
                    type(exc).__name__ == "UnsupportedTransferCoding":
                status, message = 411, "send the body with a Content-Length"
            elif isinstance(exc, (errors.LimitRequestLine, errors.LimitRequestHeaders)):
                status, message = 400, "the request line or its headers are too long"
            elif isinstance(exc, errors.ParseException):
                status, message = 400, "the request cannot be read (%s)" % exc
            else:
                self.log.exception("Error handling request")
                status, message = 500, "internal error"
            body = json.dumps({"error": message}).encode("utf-8")
            head = ("HTTP/1.1 %d %s\r\nConnection: close\r\nContent-Type: application/json; charset=utf-8\r\n"
                    "Content-Length: %d\r\nCache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n\r\n"
                    % (status, REASONS.get(status, "Error"), len(body))).encode("latin-1")
            try:
                client.sendall(head + body)
            except OSError:
                self.log.debug("Failed to send error message.")

    return JsonErrorWorker


def stderr_access_logger():
    """gunicorn's logger with each request logged to stderr (its "-" is stdout for requests),
    as the server before it did: stdout has the address alone."""
    import logging
    from gunicorn.glogging import Logger

    class StderrAccessLogger(Logger):
        def setup(self, cfg):
            super().setup(cfg)
            for handler in self.access_log.handlers:
                if isinstance(handler, logging.StreamHandler) and handler.stream is sys.stdout:
                    handler.setStream(sys.stderr)

    return StderrAccessLogger


def gunicorn_python():
    """The Python that has gunicorn (the `gunicorn` script's), when this one has not; None when
    this one has."""
    try:
        import gunicorn  # noqa: F401
        return None
    except ImportError:
        pass
    script = shutil.which("gunicorn")
    if script:
        with open(script, "rb") as f:
            first = f.readline().decode("utf-8", "replace").strip()
        if first.startswith("#!"):
            python = first[2:].split()[0]
            if os.path.basename(python) == "env":
                python = shutil.which(first[2:].split()[1]) or ""
            if python and os.path.realpath(python) != os.path.realpath(sys.executable):
                return python
    raise RuntimeError("gunicorn is not installed for this Python (Debian: apt-get install gunicorn)")


def serve(sock, workers, config, quiet):
    from gunicorn.app.base import BaseApplication

    class Application(BaseApplication):
        def load_config(self):
            settings = {
                "bind": ["fd://%d" % sock.fileno()],
                "workers": workers,
                "worker_class": "tackle_step_service.JsonErrorWorker",
                "timeout": int(config.time_limit + HARD_TIMEOUT_MARGIN),
                "graceful_timeout": 5,
                "backlog": 2048,
                "loglevel": "warning",
                "errorlog": "-",
                "accesslog": None if quiet else "-",
                "logger_class": stderr_access_logger(),
                "access_log_format": '%(h)s - - %(t)s "%(r)s" %(s)s %(b)s',
                "proc_name": "tackle-step-service",
            }
            for key, value in settings.items():
                self.cfg.set(key, value)

        def load(self):
            # Each worker loads the problem as it starts (the one the launcher loaded to check
            # the files stays in the launcher, which only watches the workers).
            return Service(config)

    Application().run()


def main(argv=None, prog=None, default_build=None):
    ap = argparse.ArgumentParser(prog=prog, description="Serve tackle's page for one problem and check its steps, with gunicorn's workers (127.0.0.1)")
    ap.add_argument("file", help="Problem description (YAML)")
    ap.add_argument("--port", type=int, default=0, help="Port (0: a free one; the address is printed)")
    ap.add_argument("--workers", type=int, default=0, help="Worker processes, each checking one request at a time (0, the default: one a core)")
    ap.add_argument("--rubric", help="The rubric for whole solutions (YAML), as for tackle check --rubric")
    ap.add_argument("--origin", action="append", default=[],
                    help="The origin (scheme://host[:port]) of a page elsewhere that may post here (repeatable); "
                         "else only the page this server serves")
    ap.add_argument("--phase", default="", help="A phase of a description with 'phases', by name")
    ap.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT,
                    help="Seconds a solution's checking may take: steps not begun by then are undecided (default 5)")
    ap.add_argument("--build", help="tackle's build directory (its python/ has the module)")
    ap.add_argument("--quiet", action="store_true", help="Do not log each request")
    args = ap.parse_args(argv)
    name = ap.prog
    if not 0 <= args.port <= 65535:
        ap.error("--port must be from 0 to 65535")
    if not 0 <= args.workers <= 256:
        ap.error("--workers must be from 0 to 256 (0: one a core)")
    if not 0 < args.time_limit <= 3600:
        ap.error("--time-limit must be more than 0 and at most 3600 seconds")
    for origin in args.origin:
        try:
            check_origin(origin)
        except ValueError as e:
            ap.error(str(e))
    try:
        python = gunicorn_python()
    except RuntimeError as e:
        print("%s: %s" % (name, e), file=sys.stderr)
        return 1
    if python:
        # This Python has no gunicorn: the launcher again under the one that has (Debian's
        # python3 for its gunicorn package), the module found as it is here.
        if os.environ.get("TACKLE_STEP_REEXEC"):
            print("%s: gunicorn is not installed for this Python (Debian: apt-get install gunicorn)" % name, file=sys.stderr)
            return 1
        env = dict(os.environ, TACKLE_STEP_REEXEC="1")
        os.execve(python, [python, os.path.abspath(sys.argv[0])] + (sys.argv[1:] if argv is None else list(argv)), env)
    for d in [args.build, os.environ.get("TACKLE_BUILD_DIR"), default_build]:
        if d and os.path.isdir(os.path.join(d, "python")):
            sys.path.insert(0, os.path.join(d, "python"))
            break
    config = Config(args.file, phase=args.phase, rubric_file=args.rubric, origins=args.origin, time_limit=args.time_limit)
    try:
        Service(config)  # the files read once here: a problem in them is said now, not by each worker
    except ImportError as e:
        print("%s: cannot import tackle's Python module (%s): give --build DIR, or install tackle" % (name, e), file=sys.stderr)
        return 1
    except (OSError, ValueError) as e:
        print("%s: %s" % (name, e), file=sys.stderr)
        return 1
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind(("127.0.0.1", args.port))
    except OSError as e:
        print("%s: cannot listen on 127.0.0.1:%d (%s)" % (name, args.port, e.strerror or e), file=sys.stderr)
        return 1
    sock.listen(2048)
    sock.set_inheritable(True)
    config.port = sock.getsockname()[1]
    print("http://127.0.0.1:%d/" % config.port, flush=True)
    serve(sock, args.workers or len(os.sched_getaffinity(0)), config, args.quiet)
    return 0


if __name__ == "__main__":
    sys.exit(main())
