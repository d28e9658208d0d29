-- book.lua (bench, chapter 1): the pandoc filter that makes a chapter's page of the book.
--
-- Listings. A code block of class `listing` names a file of the chapter's clean source
-- (BOOK_SOURCE, build/source/chapterN) and what to show of it:
--   ```{.listing file="lib/render.c" function="render_sample"}```  a function's definition
--       (or, in a header, its prototype), with the comment block just above it;
--   type="Name"      a typedef, struct or enum, with its comment;
--   define="NAME"    a #define (continuation lines too), with its comment;
--   name="x"         any of those, or a variable;
--   head="yes"       the file's opening: its first comment, include guard and includes;
--   from="text" to="text"  a marked block: from the first line containing `from` to the
--                    first line at or after it containing `to`;
--   only file=...    the whole file.
-- function, type, define and name take several names separated by spaces; the listing
-- shows them in the file's order, in one block where only blank lines part them. The
-- text is taken from the source when the page is built and shown with its file and line
-- numbers; a directive that finds nothing stops the build with a message naming the page,
-- the directive and what is missing. Each listing's lines are appended to BOOK_COVERAGE as
-- "FILE FIRST LAST" (bench/book/coverage.sh checks that they cover the chapter's diff).
--
-- Figures and tables. ```{.figure name="ch07_figure7_captioned" lab="chapter=7"}``` shows
-- BOOK_FIGURES/NAME.png (build/figures; BOOK_FIGURES_LINK is the same folder as the page
-- links it) with the block's text as caption and a link to the lab
-- (../lab/index.html#FRAGMENT) when BOOK_LAB is built; ```{.table name="ch03_table"}```
-- shows NAME.csv. Missing, either says how to make it. Links to other docs/ pages
-- (NAME.md) go to their pages of the book, and a docs/ page's "../PATH" to the
-- repository's file (BOOK_ROOT: the repository's top, as the page links it).
local chapter = os.getenv("BOOK_CHAPTER") or "?"
local source = os.getenv("BOOK_SOURCE") or ""
local coverage = os.getenv("BOOK_COVERAGE")
local figures = os.getenv("BOOK_FIGURES") or "build/figures"
local figures_link = os.getenv("BOOK_FIGURES_LINK") or "../figures" -- the same, from the page
local lab = os.getenv("BOOK_LAB") or "build/lab/index.html"
local page = (PANDOC_STATE.input_files or {})[1] or "the page"

local function fail(directive, message)
  error("\n" .. page .. ": listing {" .. directive .. "}: " .. message .. "\n", 0)
end

local function exists(path)
  local f = io.open(path, "r")
  if f then f:close() end
  return f ~= nil
end

local function read_lines(path)
  local f = io.open(path, "r")
  if not f then return nil end
  local lines = {}
  for line in f:lines() do lines[#lines + 1] = line end
  f:close()
  return lines
end

-- Each line without its comments, strings and character constants (so that braces and
-- parentheses in them are not counted); `comment[i]` says whether line i is only comment.
local function strip(lines)
  local code, only_comment, in_comment = {}, {}, false
  for i, line in ipairs(lines) do
    local out, j, had_comment = {}, 1, in_comment
    while j <= #line do
      local c, two = line:sub(j, j), line:sub(j, j + 1)
      if in_comment then
        if two == "*/" then in_comment = false; j = j + 2 else j = j + 1 end
      elseif two == "/*" then in_comment = true; had_comment = true; j = j + 2
      elseif two == "//" then had_comment = true; break
      elseif c == '"' or c == "'" then
        local k = j + 1
        while k <= #line and line:sub(k, k) ~= c do
          if line:sub(k, k) == "\\" then k = k + 1 end
          k = k + 1
        end
        out[#out + 1] = c .. c
        j = k + 1
      else out[#out + 1] = c; j = j + 1 end
    end
    code[i] = table.concat(out)
    only_comment[i] = had_comment and not code[i]:find("%S")
  end
  return code, only_comment
end

-- The file's top-level items: {first, last, kind, names}, first..last including the
-- comment block directly above (no blank line between). Kinds: "define", "include",
-- "guard", "comment", "code" (functions, prototypes, types, variables).
local function items_of(lines)
  local code, only_comment = strip(lines)
  local items, i, n = {}, 1, #lines
  local guard = nil
  while i <= n do
    if not lines[i]:find("%S") then
      i = i + 1
    elseif only_comment[i] then
      local first = i
      while i <= n and only_comment[i] do i = i + 1 end
      if i <= n and lines[i]:find("%S") then
        -- the comment belongs to the item that follows it; mark where it starts
        items.pending = items.pending or first
      else
        items[#items + 1] = {first = first, last = i - 1, kind = "comment", names = {}}
      end
    else
      local first = items.pending or i
      items.pending = nil
      local item = {first = first, names = {}}
      local text = code[i]
      if text:match("^%s*#") then
        local last = i
        while lines[last]:match("\\%s*$") and last < n do last = last + 1 end
        local directive, name = text:match("^%s*#%s*(%a+)%s*([%w_]*)")
        if directive == "ifndef" and not guard then
          guard = name; item.kind = "guard"
        elseif directive == "define" and name == guard then item.kind = "guard"
        elseif directive == "endif" then item.kind = "guard"
        elseif directive == "include" then item.kind = "include"
        elseif directive == "define" then item.kind = "define"; item.names[1] = name
        else item.kind = "code" end
        item.last = last
        i = last + 1
      else
        -- accumulate until the braces and parentheses close on a ";" or on the "}" of a
        -- function's body
        local depth, parens, all, last = 0, 0, {}, i
        while last <= n do
          local c = code[last]
          all[#all + 1] = c
          for ch in c:gmatch("[{}()]") do
            if ch == "{" then depth = depth + 1 elseif ch == "}" then depth = depth - 1
            elseif ch == "(" then parens = parens + 1 else parens = parens - 1 end
          end
          local joined = table.concat(all, "\n")
          if depth == 0 and parens == 0 then
            local before_brace = joined:match("^([^{]*){")
            if joined:match(";%s*$") then break end
            if before_brace and before_brace:match("%)%s*$") and joined:match("}%s*$") then break end
          end
          last = last + 1
        end
        last = math.min(last, n)
        local joined = table.concat(all, " ")
        item.kind = "code"
        item.last = last
        local head = joined:match("^([^{=]*)") or joined
        if joined:match("^%s*typedef") then
          local pointer = joined:match("%(%s*%*%s*([%w_]+)%s*%)")
          if pointer then item.names[#item.names + 1] = pointer end
          local final = joined:gsub("%b{}", ""):gsub("%b[]", ""):match("([%w_]+)%s*;%s*$")
          if final then item.names[#item.names + 1] = final end
          local tag = joined:match("^%s*typedef%s+[sue]%a+%s+([%w_]+)")
          if tag then item.names[#item.names + 1] = tag end
        elseif head:match("^%s*struct%s+[%w_]+%s*$") or head:match("^%s*enum%s+[%w_]+%s*$") then
          item.names[1] = head:match("^%s*%a+%s+([%w_]+)")
        else
          local fname = head:match("([%w_]+)%s*%(")
          if fname then
            item.names[1] = fname
            item.body = joined:find("{") ~= nil
          else
            local var = head:match("([%w_]+)%s*[%[;]") or head:match("([%w_]+)%s*$")
            if var then item.names[1] = var end
          end
        end
        i = last + 1
      end
      items[#items + 1] = item
    end
  end
  return items
end

local function find_named(items, name, kind)
  local found = {}
  for _, item in ipairs(items) do
    for _, n in ipairs(item.names) do
      if n == name then found[#found + 1] = item; break end
    end
  end
  local function fits(item)
    if kind == "define" then return item.kind == "define" end
    if kind == "function" then return item.body ~= nil end
    if kind == "type" then return item.body == nil and item.kind == "code" end
    return true
  end
  local kept = {}
  for _, item in ipairs(found) do if fits(item) then kept[#kept + 1] = item end end
  if #kept > 1 then
    local bodies = {}
    for _, item in ipairs(kept) do if item.body then bodies[#bodies + 1] = item end end
    if #bodies == 1 then kept = bodies end
  end
  return kept
end

-- The ranges {first, last} a directive names in `lines`.
local function ranges_of(attr, lines, directive)
  local items = items_of(lines)
  local ranges = {}
  local any = false
  for key, kind in pairs({["function"] = "function", type = "type", define = "define", name = "name"}) do
    local value = attr[key]
    if value then
      any = true
      for name in value:gmatch("%S+") do
        local found = find_named(items, name, kind)
        if #found == 0 then fail(directive, "no " .. kind .. " " .. name .. " in " .. attr.file)
        elseif #found > 1 then
          fail(directive, kind .. " " .. name .. " is defined " .. #found .. " times in " .. attr.file)
        end
        ranges[#ranges + 1] = {found[1].first, found[1].last}
      end
    end
  end
  if attr.head then
    any = true
    local last = 0
    for _, item in ipairs(items) do
      if item.kind == "comment" or item.kind == "include" or
         (item.kind == "guard" and item.first < (items[#items].first)) then
        last = item.last
      else break end
    end
    if last == 0 then fail(directive, attr.file .. " opens with no comment or include") end
    ranges[#ranges + 1] = {1, last}
  end
  if attr.from or attr.to then
    any = true
    if not (attr.from and attr.to) then fail(directive, "from= needs to= and to= needs from=") end
    local first, last
    for i, line in ipairs(lines) do
      if not first and line:find(attr.from, 1, true) then first = i end
      if first and line:find(attr.to, 1, true) then last = i; break end
    end
    if not first then fail(directive, "no line of " .. attr.file .. " contains \"" .. attr.from .. "\"") end
    if not last then
      fail(directive, "no line of " .. attr.file .. " from line " .. first .. " on contains \"" .. attr.to .. "\"")
    end
    ranges[#ranges + 1] = {first, last}
  end
  if not any then ranges[1] = {1, #lines} end
  table.sort(ranges, function(a, b) return a[1] < b[1] end)
  -- join ranges that only blank lines part
  local joined = {}
  for _, r in ipairs(ranges) do
    local prev = joined[#joined]
    local blank_gap = prev ~= nil
    if prev then
      for i = prev[2] + 1, r[1] - 1 do
        if lines[i]:find("%S") then blank_gap = false; break end
      end
    end
    if prev and (r[1] <= prev[2] + 1 or blank_gap) then prev[2] = math.max(prev[2], r[2])
    else joined[#joined + 1] = {r[1], r[2]} end
  end
  return joined
end

local function describe(attr)
  local words = {}
  for _, key in ipairs({"file", "function", "type", "define", "name", "head", "from", "to"}) do
    if attr[key] then words[#words + 1] = key .. '="' .. attr[key] .. '"' end
  end
  return table.concat(words, " ")
end

local listing_count = 0

local function listing(block)
  local attr = {}
  for k, v in pairs(block.attributes) do attr[k] = v end
  local directive = describe(attr)
  if not attr.file then fail(directive, "no file= given") end
  if attr.file:find("%.%.") or attr.file:sub(1, 1) == "/" then
    fail(directive, "file= must be a path inside the chapter's source")
  end
  local path = source .. "/" .. attr.file
  local lines = read_lines(path)
  if not lines then fail(directive, "no file " .. attr.file .. " in chapter " .. chapter .. "'s source (" .. path .. ")") end
  local ranges = ranges_of(attr, lines, directive)
  listing_count = listing_count + 1
  local out
  if coverage then out = io.open(coverage, "a") end
  local blocks = {}
  local where = {}
  for _, r in ipairs(ranges) do
    where[#where + 1] = r[1] == r[2] and tostring(r[1]) or (r[1] .. "–" .. r[2])
  end
  local exercises = {}
  for _, r in ipairs(ranges) do
    for i = r[1], r[2] do
      for ex in lines[i]:gmatch("Exercise (%d+%.%d+)") do exercises[#exercises + 1] = ex end
    end
  end
  local caption = {pandoc.Link(pandoc.Code(attr.file), "../source/chapter" .. chapter .. "/" .. attr.file),
                   pandoc.Str(", line" .. ((#ranges > 1 or ranges[1][1] ~= ranges[1][2]) and "s " or " ")
                              .. table.concat(where, ", "))}
  if #exercises > 0 then
    caption[#caption + 1] = pandoc.Space()
    caption[#caption + 1] = pandoc.Span({pandoc.Str("(Exercise " .. table.concat(exercises, ", ") .. ")")},
                                        {class = "exercise"})
  end
  blocks[1] = pandoc.Div({pandoc.Plain(caption)}, {class = "listing-where"})
  for _, r in ipairs(ranges) do
    local text = table.concat(lines, "\n", r[1], r[2])
    blocks[#blocks + 1] = pandoc.CodeBlock(text, {class = "c numberLines", startFrom = tostring(r[1])})
    if out then out:write(attr.file .. " " .. r[1] .. " " .. r[2] .. "\n") end
  end
  if out then out:write("listing\n"); out:close() end
  return pandoc.Div(blocks, {class = "listing", ["data-directive"] = directive})
end

-- Links between docs/ pages go to their pages of the book; "../PATH" (the repository's
-- files, as docs/ links them) goes to the file, relative to the book (BOOK_ROOT).
local root = os.getenv("BOOK_ROOT") or "../.."
local function link(l)
  local target = l.target
  if target:match("^%a+:") or target:match("^#") then return nil end
  local name, anchor = target:match("^([%w_%-]+)%.md(#?.*)$")
  if name then l.target = name .. ".html" .. anchor; return l end
  local up = target:match("^%.%./(.*)$")
  if up and page:match("^docs/") then l.target = root .. "/" .. up; return l end
  return nil
end

local function figure(block)
  local name = block.attributes.name
  if not name then fail(describe(block.attributes), "a figure needs name=") end
  local n = name:match("^ch0*(%d+)_") or chapter
  local caption = pandoc.walk_block(pandoc.Div(pandoc.read(block.text, "markdown").blocks), {Link = link}).content
  local file = figures .. "/" .. name .. ".png"
  local body = {}
  if exists(file) then
    local image = pandoc.Image({pandoc.Str(name)}, figures_link .. "/" .. name .. ".png", "")
    body[#body + 1] = pandoc.Para({pandoc.Link({image}, figures_link .. "/" .. name .. ".png")})
  else
    body[#body + 1] = pandoc.Para({pandoc.Emph({pandoc.Str("Not rendered yet: "), pandoc.Code("make chapter" .. n),
      pandoc.Str(" (or "), pandoc.Code("make figures"), pandoc.Str(") writes "),
      pandoc.Code("build/figures/" .. name .. ".png"), pandoc.Str(", and "), pandoc.Code("make book"),
      pandoc.Str(" then shows it here.")})})
  end
  for _, b in ipairs(caption) do body[#body + 1] = b end
  local links = {}
  if block.attributes.lab then
    if exists(lab) then
      links[#links + 1] = pandoc.Link("Live in the lab", "../lab/index.html#" .. block.attributes.lab)
    else
      links[#links + 1] = pandoc.Str("Live in the lab once ")
      links[#links + 1] = pandoc.Code("make lab")
      links[#links + 1] = pandoc.Str(" has built it (settings " .. block.attributes.lab .. ")")
    end
    links[#links + 1] = pandoc.Str(". ")
  end
  if exists(figures .. "/index.html") then
    links[#links + 1] = pandoc.Link("In the gallery", figures_link .. "/index.html")
    links[#links + 1] = pandoc.Str(".")
  end
  if #links > 0 then body[#body + 1] = pandoc.Para(links) end
  return pandoc.Div(body, {class = "figure", ["data-figure"] = name})
end

local function csv_table(block)
  local name = block.attributes.name
  local file = figures .. "/" .. name .. ".csv"
  local f = io.open(file, "r")
  local body = {}
  if f then
    local text = f:read("a")
    f:close()
    for _, b in ipairs(pandoc.read(text, "csv").blocks) do body[#body + 1] = b end
  else
    local n = name:match("^ch0*(%d+)_") or chapter
    body[1] = pandoc.Para({pandoc.Emph({pandoc.Str("Not measured yet: "), pandoc.Code("make chapter" .. n),
      pandoc.Str(" (or "), pandoc.Code("make figures"), pandoc.Str(") writes "),
      pandoc.Code("build/figures/" .. name .. ".csv"), pandoc.Str(".")})})
  end
  local caption = pandoc.walk_block(pandoc.Div(pandoc.read(block.text, "markdown").blocks), {Link = link}).content
  for _, b in ipairs(caption) do body[#body + 1] = b end
  return pandoc.Div(body, {class = "csv-table", ["data-table"] = name})
end

-- BOOK_ITEMS="lib/a.c lib/b.h": print the top-level items of those files of the chapter's source
-- as directives, one a line, with their lines (bench/book/items.sh), and nothing else.
local function print_items(files)
  for file in files:gmatch("%S+") do
    local lines = read_lines(source .. "/" .. file)
    if not lines then error("no " .. source .. "/" .. file, 0) end
    for _, item in ipairs(items_of(lines)) do
      local key = item.kind == "define" and "define" or item.body and "function" or "name"
      local what = #item.names > 0 and (key .. "=\"" .. item.names[#item.names] .. "\"") or item.kind
      io.stdout:write(string.format("%s:%d-%d  {.listing file=\"%s\" %s}\n", file, item.first, item.last, file, what))
    end
  end
end
if os.getenv("BOOK_ITEMS") then print_items(os.getenv("BOOK_ITEMS")); os.exit(0) end

return {{Link = link}, {
  CodeBlock = function(block)
    if block.classes:includes("listing") then return listing(block) end
    if block.classes:includes("figure") then return figure(block) end
    if block.classes:includes("table") then return csv_table(block) end
  end,
}}
