"""RoBIOS LCD group: what does more than call one method of the LCD (protocol.json's "calls": text,
colours, fonts, pixels, lines, images) with the request's values: printing at a position, the
cursor, modes and the soft-key menu (which the viewer is told of), the size, filled shapes."""

from eyesim.calls.errors import checked_arguments, component_of
from eyesim.robot.components.lcd import HEIGHT, WIDTH, Lcd


def _lcd(robot) -> Lcd:
    return component_of(robot, Lcd)


def lcd_set_printf(sim, robot, request):
    row, column, text = request.args
    lcd = _lcd(robot)
    with checked_arguments():
        lcd.set_position(row, column)
    lcd.print(text)
    return (0,)


def lcd_get_pos(sim, robot, request):
    lcd = _lcd(robot)
    return (0, lcd.row, lcd.column)


def lcd_set_mode(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_mode(*request.args)
    sim.events.menu(robot)  # the viewer needs to know whether the menu bar shows, and which way up
    return (0,)


def lcd_menu(sim, robot, request):
    _lcd(robot).set_menu(list(request.args))
    sim.events.menu(robot)
    return (0,)


def lcd_menu_i(sim, robot, request):
    with checked_arguments():
        _lcd(robot).set_menu_entry(*request.args)
    sim.events.menu(robot)
    return (0,)


def lcd_get_size(sim, robot, request):
    _lcd(robot)
    return (0, WIDTH, HEIGHT)


def lcd_area(sim, robot, request):
    x1, y1, x2, y2, color, fill = request.args
    with checked_arguments():
        _lcd(robot).area(x1, y1, x2, y2, color, bool(fill))
    return (0,)


def lcd_circle(sim, robot, request):
    x, y, radius, color, fill = request.args
    with checked_arguments():
        _lcd(robot).circle(x, y, radius, color, bool(fill))
    return (0,)


HANDLERS = {
    "LCD_SET_PRINTF": lcd_set_printf,
    "LCD_MENU": lcd_menu,
    "LCD_GET_POS": lcd_get_pos,
    "LCD_SET_MODE": lcd_set_mode,
    "LCD_MENU_I": lcd_menu_i,
    "LCD_GET_SIZE": lcd_get_size,
    "LCD_AREA": lcd_area,
    "LCD_CIRCLE": lcd_circle,
}
