#!/usr/bin/env python3
"""Asks a window whether its GUI thread answers: _NET_WM_PING, as a window manager does
before it calls a window "not responding" (standard library and libX11 only).

Usage: python3 wm-ping.py WINDOW OUTFILE [INTERVAL_MS]

Sends WINDOW (an X window id, decimal or 0x hex) a _NET_WM_PING client message, waits for
the answer the toolkit sends to the root window, writes "SENT ANSWERED" (wall-clock seconds)
as one line of OUTFILE, and sends the next one INTERVAL_MS (default 10) after the answer,
until it is killed. Qt answers a ping from its GUI thread's event loop, so an answer that
takes long is a window that stalled for that long; a stall that begins between two pings is
seen up to INTERVAL_MS short.
"""
import ctypes
import select
import sys
import time

CLIENT_MESSAGE = 33
SUBSTRUCTURE_NOTIFY = 1 << 19
STRUCTURE_NOTIFY = 1 << 17


class ClientMessage(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                ("display", ctypes.c_void_p), ("window", ctypes.c_ulong),
                ("message_type", ctypes.c_ulong), ("format", ctypes.c_int),
                ("data", ctypes.c_long * 5)]


class XEvent(ctypes.Union):
    _fields_ = [("type", ctypes.c_int), ("xclient", ClientMessage), ("pad", ctypes.c_long * 24)]


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        window = int(argv[1], 0)
        interval = (float(argv[3]) if len(argv) > 3 else 10.0) / 1000.0
    except ValueError:
        print("wm-ping.py: WINDOW must be a window id and INTERVAL_MS a number", file=sys.stderr)
        return 2
    x = ctypes.cdll.LoadLibrary("libX11.so.6")
    x.XOpenDisplay.restype = ctypes.c_void_p
    x.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x.XDefaultRootWindow.restype = ctypes.c_ulong
    x.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
    x.XInternAtom.restype = ctypes.c_ulong
    x.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
    x.XSelectInput.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_long]
    x.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long,
                             ctypes.POINTER(XEvent)]
    x.XFlush.argtypes = [ctypes.c_void_p]
    x.XPending.argtypes = [ctypes.c_void_p]
    x.XNextEvent.argtypes = [ctypes.c_void_p, ctypes.POINTER(XEvent)]
    x.XConnectionNumber.argtypes = [ctypes.c_void_p]
    # A window that is gone makes XSendEvent fail: ignore X errors, the script stops us.
    handler_type = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p)
    ignore = handler_type(lambda d, e: 0)
    x.XSetErrorHandler(ignore)
    dpy = x.XOpenDisplay(None)
    if not dpy:
        print("wm-ping.py: cannot open the display", file=sys.stderr)
        return 1
    root = x.XDefaultRootWindow(dpy)
    protocols = x.XInternAtom(dpy, b"WM_PROTOCOLS", 0)
    ping = x.XInternAtom(dpy, b"_NET_WM_PING", 0)
    # Qt sends the answer to the root window for one of these (which, by its version).
    x.XSelectInput(dpy, root, STRUCTURE_NOTIFY | SUBSTRUCTURE_NOTIFY)
    fd = x.XConnectionNumber(dpy)
    out = open(argv[2], "w", buffering=1)
    serial = 0
    ev = XEvent()
    while True:
        serial += 1
        msg = XEvent()
        msg.xclient.type = CLIENT_MESSAGE
        msg.xclient.window = window
        msg.xclient.message_type = protocols
        msg.xclient.format = 32
        msg.xclient.data[0] = ping
        msg.xclient.data[1] = serial
        msg.xclient.data[2] = window
        sent = time.time()
        x.XSendEvent(dpy, window, 0, 0, ctypes.byref(msg))
        x.XFlush(dpy)
        answered = None
        while answered is None:
            while x.XPending(dpy):
                x.XNextEvent(dpy, ctypes.byref(ev))
                if (ev.type == CLIENT_MESSAGE and ev.xclient.message_type == protocols
                        and ev.xclient.data[0] == ping and ev.xclient.data[1] == serial):
                    answered = time.time()
            if answered is None:
                select.select([fd], [], [], 0.5)
        out.write("%.6f %.6f\n" % (sent, answered))
        time.sleep(interval)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
